// `fourier` (src/methods/fourierMethod.ts): the film's XYZ as the Airy series per fragment
// (airySeries.glsl), by the bins where the film has no real optical path or the series needs more
// than TFC_AIRY_SERIES_MAX_ORDERS terms. A dispersive film or inside has no series in the path
// alone (docs/physics.md#a-dispersive-film): the dispersive bins take it. A line source's transform
// never decays, so the series has no end: the bins sum its lines directly (binnedIntegration.glsl).
#ifndef THIN_FILM_FOURIER_METHOD
#define THIN_FILM_FOURIER_METHOD

#include "airySeries.glsl"
#include "binnedIntegration.glsl"
#include "filmSideOptics.glsl"

TFC_FILM_COLOR tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
#ifdef TFC_DISPERSIVE
  return tfcDispersiveBinnedXyz(fromInside, thicknessNm, cosIncidence, 0);
#else
  FilmOptics o = tfcSideFilmOptics(fromInside, thicknessNm, cosIncidence);
  AirySeriesTerms t[TFC_FILM_CHANNELS];
  tfcAirySeriesTermsOf(o, t);
  float x = o.opticalPathNm.x;
  return uLightLineCount == 0 && o.opticalPathNm.y == 0.0 && (TFC_AIRY_SERIES_TRUNCATED == 1 || tfcAirySeriesConvergesAt(t, x)) ? tfcAirySeriesSum(t, x) : tfcBinnedXyz(o, 0.0);
#endif
}

#endif

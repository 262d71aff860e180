// `exact` (src/methods/exactMethod.ts): the film's XYZ as the binned spectral integral per fragment
// (eqs 15–18 over the film reflectance of eqs 1–14). TFC_DISPERSIVE: the film's or the inside's
// index depends on λ (medium.glsl), and the dispersive bins take it. TFC_FILM_LAYERS: a stack of
// films, its recursion per bin (transferMatrix.glsl), the thickness the field's for its `d` layers.
#ifndef THIN_FILM_EXACT_METHOD
#define THIN_FILM_EXACT_METHOD

#include "binnedIntegration.glsl"
#include "filmSideOptics.glsl"
#ifdef TFC_FILM_LAYERS
#include "transferMatrix.glsl"
#endif

TFC_FILM_COLOR tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
#if defined(TFC_FILM_LAYERS)
  return tfcLayersBinnedXyz(uNOutside, fromInside, thicknessNm, cosIncidence);
#elif defined(TFC_DISPERSIVE)
  return tfcDispersiveBinnedXyz(fromInside, thicknessNm, cosIncidence, 0);
#else
  return tfcBinnedXyz(tfcSideFilmOptics(fromInside, thicknessNm, cosIncidence), 0.0);
#endif
}

#endif

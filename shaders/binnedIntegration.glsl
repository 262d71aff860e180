// XYZ of the reflected light, eqs (15)-(18), by TFC_SPECTRAL_BINS equal wavelength bins over
// TFC_LAMBDA_MIN_NM-TFC_LAMBDA_MAX_NM (LAMBDA_MIN_NM, LAMBDA_MAX_NM of the TypeScript, set by spectralBinDefines): X = sum over bins of W_bin * mean R over the bin's phase window.
// uSpectralBins (TFC_SPECTRAL_BINS x 1, RGBA float) holds each bin's integral of I_in x̄, ȳ, z̄ / k,
// computed once in TypeScript. Mirrors binnedXyz in src/physics/binnedIntegration.ts.
#ifndef THIN_FILM_SPECTRAL
#define THIN_FILM_SPECTRAL
#include "filmReflectance.glsl"

#ifndef TFC_SPECTRAL_BINS
#define TFC_SPECTRAL_BINS 90
#endif
// The bins integrated, first <= b < end: significantBins (TypeScript) drops the tails where the
// illuminant times the colour-matching functions hardly matters.
#ifndef TFC_SPECTRAL_BIN_FIRST
#define TFC_SPECTRAL_BIN_FIRST 0
#endif
#ifndef TFC_SPECTRAL_BIN_END
#define TFC_SPECTRAL_BIN_END TFC_SPECTRAL_BINS
#endif

uniform sampler2D uSpectralBins;

// extraHalfWidthPerInvNm widens each bin's phase window (in quadrature) by that × (nm / λ):
// the table pass averages over a cell's thickness range with it.
vec3 binnedXyz(FilmOptics o, float extraHalfWidthPerInvNm) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  vec2 path = o.opticalPathNm;
  vec3 xyz = vec3(0.0);
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    float r = 0.0;
    if (path.y != 0.0) {
      r = reflectanceAt(o, 0.5 * (l1 + l2));
    } else {
      float center = 3.141592653589793 * path.x * (1.0 / l1 + 1.0 / l2);
      float binHalf = 3.141592653589793 * path.x * (1.0 / l1 - 1.0 / l2);
      float extra = 2.0 * extraHalfWidthPerInvNm / (l1 + l2);
      float halfWidth = length(vec2(binHalf, extra));
      for (int i = 0; i < TFC_FILM_CHANNELS; i++) r += meanChannelReflectance(o.channels[i], center, halfWidth);
      r /= float(TFC_FILM_CHANNELS);
    }
    xyz += r * texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz;
  }
  return xyz;
}

#ifdef TFC_DISPERSIVE
#include "filmIndex.glsl"

// The same bins for a film whose index depends on λ (mirrors dispersiveBinnedXyz in
// src/physics/binnedIntegration.ts): each bin's Fresnel terms at n_b of its centre, its phase window
// from the optical path at its two ends, 2π Δ(λ)/λ; cellNm widens it by a table cell's thickness range.
vec3 dispersiveBinnedXyz(float nOutside, float nInside, float thicknessNm, float cosIncidence, float cellNm) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  float pathLow = filmPathPerNm(float(TFC_LAMBDA_MIN_NM) + float(TFC_SPECTRAL_BIN_FIRST) * width, nOutside, cosIncidence) * thicknessNm;
  vec3 xyz = vec3(0.0);
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    float center = 0.5 * (l1 + l2);
    FilmOptics o = filmOptics(nOutside, filmIndexAt(center), nInside, thicknessNm, cosIncidence);
    float pathHigh = filmPathPerNm(l2, nOutside, cosIncidence) * thicknessNm;
    float r = 0.0;
    if (o.opticalPathNm.y != 0.0) {
      r = reflectanceAt(o, center);
    } else {
      float phase = 3.141592653589793 * (pathLow / l1 + pathHigh / l2);
      float binHalf = 3.141592653589793 * (pathLow / l1 - pathHigh / l2);
      float extra = 3.141592653589793 * filmPathPerNm(center, nOutside, cosIncidence) * cellNm / center;
      float halfWidth = length(vec2(binHalf, extra));
      for (int i = 0; i < TFC_FILM_CHANNELS; i++) r += meanChannelReflectance(o.channels[i], phase, halfWidth);
      r /= float(TFC_FILM_CHANNELS);
    }
    xyz += r * texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz;
    pathLow = pathHigh;
  }
  return xyz;
}
#endif

#endif

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
// R of one bin: the closed-form mean over its phase window [phase - halfWidth, phase + halfWidth], or
// R at its centre for an evanescent film (no fringes to average).
float tfcBinReflectance(FilmOptics o, float centerNm, float phase, float halfWidth) {
  if (o.opticalPathNm.y != 0.0) return tfcReflectanceAt(o, centerNm);
  float r = 0.0;
  for (int i = 0; i < TFC_FILM_CHANNELS; i++) r += tfcMeanChannelReflectance(o.channels[i], phase, halfWidth);
  return r / float(TFC_FILM_CHANNELS);
}

vec3 tfcBinnedXyz(FilmOptics o, float extraHalfWidthPerInvNm) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  vec2 path = o.opticalPathNm;
  vec3 xyz = vec3(0.0);
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    float center = 3.141592653589793 * path.x * (1.0 / l1 + 1.0 / l2);
    float binHalf = 3.141592653589793 * path.x * (1.0 / l1 - 1.0 / l2);
    float extra = 2.0 * extraHalfWidthPerInvNm / (l1 + l2);
    xyz += tfcBinReflectance(o, 0.5 * (l1 + l2), center, length(vec2(binHalf, extra))) * texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz;
  }
  return xyz;
}

#ifdef TFC_DISPERSIVE
#include "filmIndex.glsl"

// What a dispersive film's bin needs: the optics at n_b of its centre, and Re Δ per nm of
// thickness at its two ends. Per fragment from the index (dispersiveBinnedXyz), or
// per table row from float64 terms (filmTable.glsl, which defines TFC_DISPERSIVE_ROWS).
struct DispersiveBin { FilmOptics optics; float pathPerNmLow; float pathPerNmHigh; };

#ifdef TFC_DISPERSIVE_ROWS
uniform sampler2D uDispersiveRows;

// Row y, bin b: TFC_DISPERSIVE_BIN_TEXELS texels from src/film/dispersiveRows.ts, all read here.
#define TFC_DISPERSIVE_BIN_TEXELS_READ 4
#if TFC_DISPERSIVE_BIN_TEXELS != TFC_DISPERSIVE_BIN_TEXELS_READ
#error "the dispersive rows' texels per bin differ from what dispersiveBin reads"
#endif
DispersiveBin tfcDispersiveBin(int y, int b, float thicknessNm, float nOutside, float nInside, float cosIncidence) {
  vec4 t0 = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + 0, y), 0);
  vec4 t1 = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + 1, y), 0);
  vec4 t2 = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + 2, y), 0);
  vec4 t3 = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + 3, y), 0);
  DispersiveBin d;
  d.optics.channels[0] = AiryTerms(t0.xy, t0.zw, t1.xy);
#ifdef TFC_BOTH_CHANNELS
  d.optics.channels[1] = AiryTerms(t1.zw, t2.xy, t2.zw);
#endif
  d.optics.opticalPathNm = t3.xy * thicknessNm;
  d.pathPerNmLow = t3.z;
  d.pathPerNmHigh = t3.w;
  return d;
}
#else
DispersiveBin tfcDispersiveBin(int y, int b, float thicknessNm, float nOutside, float nInside, float cosIncidence) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
  float center = l1 + 0.5 * width;
  DispersiveBin d;
  d.optics = tfcFilmOptics(nOutside, tfcFilmIndexAt(center), nInside, thicknessNm, cosIncidence);
  d.pathPerNmLow = tfcFilmPathPerNm(l1, nOutside, cosIncidence);
  d.pathPerNmHigh = tfcFilmPathPerNm(l1 + width, nOutside, cosIncidence);
  return d;
}
#endif

// The bins of a film whose index depends on λ (mirrors dispersiveBinnedXyz in
// src/physics/binnedIntegration.ts): each bin's Fresnel terms at n_b of its centre, its phase window
// from the optical path at its two ends, [2π Δ(λ2)/λ2, 2π Δ(λ1)/λ1]. `row`: the table row of
// TFC_DISPERSIVE_ROWS (unused per fragment).
vec3 tfcDispersiveBinnedXyz(float nOutside, float nInside, float thicknessNm, float cosIncidence, int row) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  vec3 xyz = vec3(0.0);
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    float center = 0.5 * (l1 + l2);
    DispersiveBin d = tfcDispersiveBin(row, b, thicknessNm, nOutside, nInside, cosIncidence);
    float low = d.pathPerNmLow * thicknessNm / l1;
    float high = d.pathPerNmHigh * thicknessNm / l2;
    xyz += tfcBinReflectance(d.optics, center, 3.141592653589793 * (low + high), 3.141592653589793 * (low - high)) * texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz;
  }
  return xyz;
}
#endif

#endif

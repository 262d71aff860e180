// XYZ of the reflected light, eqs (15)-(18), by TFC_SPECTRAL_BINS equal wavelength bins over
// TFC_LAMBDA_MIN_NM-TFC_LAMBDA_MAX_NM (LAMBDA_MIN_NM, LAMBDA_MAX_NM of the TypeScript, set by spectralBinDefines): X = sum over bins of W_bin * mean R over the bin's phase window.
// uSpectralBins (TFC_SPECTRAL_BINS x 2, RGBA float) holds in row 0 each bin's integral of I_in x̄, ȳ, z̄ / k,
// in row 1 its light's mean σ = 1/λ less the bin's middle σ and the half-width √3 sd in σ of the
// box with its variance (SpectralBins.windows): a film's phase 2π Re Δ σ is linear in σ, so that box
// is the bin's phase window. Computed once in TypeScript. Mirrors binnedXyz in src/physics/binnedIntegration.ts.
#ifndef THIN_FILM_SPECTRAL
#define THIN_FILM_SPECTRAL
#include "filmReflectance.glsl"
#include "environmentMatrix.glsl"

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

// A line source (src/physics/lightLines.ts): uLightLineCount lines (0: the light has a spectrum and
// the bins integrate it), each uLightLines[i] = (p x̄, ȳ, z̄(λ)/k, λ in nm). The lines are bins of no
// width [λ, λ] (binsXyz in the TypeScript): R at each line, its phase window only the extra
// half-width, times its weight; the bins' weights are then 0 and not read.
#ifndef TFC_LIGHT_LINES_MAX
#define TFC_LIGHT_LINES_MAX 2
#endif
uniform vec4 uLightLines[3 * TFC_LIGHT_LINES_MAX];
uniform int uLightLineCount;

// A bin's or a line's weights for the film's colour (environmentMatrix.glsl): each bin's R serves
// every column of M, its weights a mat3 of plane p's weights in column p (rows 0, 2, 3 of
// uSpectralBins; plane p's lines at uLightLines[p * TFC_LIGHT_LINES_MAX + i]).
#ifdef TFC_ENVIRONMENT_MATRIX
TFC_FILM_COLOR tfcBinWeight(int b) {
  return mat3(texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz, texelFetch(uSpectralBins, ivec2(b, 2), 0).xyz, texelFetch(uSpectralBins, ivec2(b, 3), 0).xyz);
}
TFC_FILM_COLOR tfcLineWeight(int i) {
  return mat3(uLightLines[i].xyz, uLightLines[TFC_LIGHT_LINES_MAX + i].xyz, uLightLines[2 * TFC_LIGHT_LINES_MAX + i].xyz);
}
#else
TFC_FILM_COLOR tfcBinWeight(int b) { return texelFetch(uSpectralBins, ivec2(b, 0), 0).xyz; }
TFC_FILM_COLOR tfcLineWeight(int i) { return uLightLines[i].xyz; }
#endif

// R of one bin (binReflectance in the TypeScript): the closed-form mean over its phase window
// [phase - halfWidth, phase + halfWidth] of the real phase, an absorbing film's attenuation
// a = e^{-Im φ} at the bin's centre folded into t_ab t_ba r_bc and r_ba r_bc; R at its centre for an
// evanescent film (Re Δ = 0: no fringes to average).
float tfcBinReflectance(FilmOptics o, float centerNm, float phase, float halfWidth) {
  vec2 path = o.opticalPathNm;
  if (path.x == 0.0 && path.y != 0.0) return tfcReflectanceAt(o, centerNm);
  float a = exp(-6.283185307179586 * path.y / centerNm);
  float r = 0.0;
  for (int i = 0; i < TFC_FILM_CHANNELS; i++) {
    AiryTerms c = o.channels[i];
    r += tfcMeanChannelReflectance(AiryTerms(c.rab, a * c.multiple, a * c.roundTrip), phase, halfWidth);
  }
  return r / float(TFC_FILM_CHANNELS);
}

// extraHalfWidthPerInvNm widens each bin's phase window (in quadrature) by that × (nm / λ):
// the table pass averages over a cell's thickness range with it.
TFC_FILM_COLOR tfcBinnedXyz(FilmOptics o, float extraHalfWidthPerInvNm) {
  if (uLightLineCount > 0) {
    TFC_FILM_COLOR lines = TFC_FILM_COLOR(0.0);
    for (int i = 0; i < TFC_LIGHT_LINES_MAX && i < uLightLineCount; i++) {
      float l = uLightLines[i].w;
      lines += tfcBinReflectance(o, l, 6.283185307179586 * o.opticalPathNm.x / l, extraHalfWidthPerInvNm / l) * tfcLineWeight(i);
    }
    return lines;
  }
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  float path = o.opticalPathNm.x;
  TFC_FILM_COLOR xyz = TFC_FILM_COLOR(0.0);
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    vec2 spread = texelFetch(uSpectralBins, ivec2(b, 1), 0).xy;
    float sigma = 0.5 * (1.0 / l1 + 1.0 / l2) + spread.x;
    float center = 6.283185307179586 * path * sigma;
    float binHalf = 6.283185307179586 * path * spread.y;
    xyz += tfcBinReflectance(o, 1.0 / sigma, center, length(vec2(binHalf, extraHalfWidthPerInvNm * sigma))) * tfcBinWeight(b);
  }
  return xyz;
}

#ifdef TFC_DISPERSIVE
#include "filmMedia.glsl"
#include "medium.glsl"

// What a bin of a film whose media depend on λ needs: the optics at ñ of its centre, and Re Δ per
// nm of thickness at its two ends. Per fragment from the media's knots, or per table row from
// float64 terms (filmTable.glsl, which defines TFC_DISPERSIVE_ROWS).
struct DispersiveBin { FilmOptics optics; float pathPerNmLow; float pathPerNmHigh; };

// The media at λ for light arriving from outside, or from inside (the far wall: the inside is then
// transparent, and its n the light's n_a): n_a, ñ_b, ñ_c.
void tfcBinMedia(float lambdaNm, bool fromInside, out float na, out vec2 nb, out vec2 nc) {
  vec2 inside;
  tfcKnotMedia(tfcMediaAt(lambdaNm), nb, inside);
  na = fromInside ? inside.x : uNOutside;
  nc = fromInside ? vec2(uNOutside, 0.0) : inside;
}

float tfcBinPathPerNm(float lambdaNm, bool fromInside, float cosIncidence) {
  float na;
  vec2 nb, nc;
  tfcBinMedia(lambdaNm, fromInside, na, nb, nc);
  return tfcFilmPathPerNm(nb, na, cosIncidence);
}

// The optics at a bin's centre from the knots (per fragment; in the table pass the bare interface at d = 0).
FilmOptics tfcBinOptics(float centerNm, float thicknessNm, bool fromInside, float cosIncidence) {
  float na;
  vec2 nb, nc;
  tfcBinMedia(centerNm, fromInside, na, nb, nc);
  return tfcFilmOptics(na, nb, nc, thicknessNm, cosIncidence);
}

#ifdef TFC_DISPERSIVE_ROWS
#include "texelRecord.glsl"
uniform sampler2D uDispersiveRows;

// Row y, bin b: a record of src/film/dispersiveRows.ts's DISPERSIVE_BIN, read by its names.
DispersiveBin tfcDispersiveBin(int y, int b, float thicknessNm, bool fromInside, float cosIncidence) {
  vec4 t[TFC_DISPERSIVE_BIN_TEXELS];
  for (int i = 0; i < TFC_DISPERSIVE_BIN_TEXELS; i++) t[i] = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + i, y), 0);
  DispersiveBin d;
  d.optics.channels[0] = AiryTerms(TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_RAB_0), TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_MULTIPLE_0), TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_ROUND_TRIP_0));
#ifdef TFC_BOTH_CHANNELS
  d.optics.channels[1] = AiryTerms(TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_RAB_1), TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_MULTIPLE_1), TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_ROUND_TRIP_1));
#endif
  d.optics.opticalPathNm = TFC_RECORD_VEC2(t, TFC_DISPERSIVE_BIN_PATH_PER_NM) * thicknessNm;
  // The rows hold a film's terms (d > 0); at d = 0 filmOptics decides (the bare interface), as in the reference.
  if (thicknessNm == 0.0) {
    const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
    d.optics = tfcBinOptics(float(TFC_LAMBDA_MIN_NM) + (float(b) + 0.5) * width, 0.0, fromInside, cosIncidence);
  }
  d.pathPerNmLow = TFC_RECORD_FLOAT(t, TFC_DISPERSIVE_BIN_PATH_PER_NM_LOW);
  d.pathPerNmHigh = TFC_RECORD_FLOAT(t, TFC_DISPERSIVE_BIN_PATH_PER_NM_HIGH);
  return d;
}
#else
DispersiveBin tfcDispersiveBin(int y, int b, float thicknessNm, bool fromInside, float cosIncidence) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
  DispersiveBin d;
  d.optics = tfcBinOptics(l1 + 0.5 * width, thicknessNm, fromInside, cosIncidence);
  d.pathPerNmLow = tfcBinPathPerNm(l1, fromInside, cosIncidence);
  d.pathPerNmHigh = tfcBinPathPerNm(l1 + width, fromInside, cosIncidence);
  return d;
}
#endif

// The bins of a film whose media depend on λ (mirrors dispersiveBinnedXyz in
// src/physics/binnedIntegration.ts): each bin's Fresnel terms at ñ of its centre, its phase 2π Re Δ(λ)/λ
// from the optical path at its two ends, linear in σ between them. `row`: the table row of
// TFC_DISPERSIVE_ROWS (unused per fragment).
TFC_FILM_COLOR tfcDispersiveBinnedXyz(bool fromInside, float thicknessNm, float cosIncidence, int row) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  TFC_FILM_COLOR xyz = TFC_FILM_COLOR(0.0);
  // A line source's lines: the media at each line's λ from their knots (the rows hold bins only).
  for (int i = 0; i < TFC_LIGHT_LINES_MAX && i < uLightLineCount; i++) {
    float l = uLightLines[i].w;
    float path = tfcBinPathPerNm(l, fromInside, cosIncidence) * thicknessNm;
    xyz += tfcBinReflectance(tfcBinOptics(l, thicknessNm, fromInside, cosIncidence), l, 6.283185307179586 * path / l, 0.0) * tfcLineWeight(i);
  }
  if (uLightLineCount > 0) return xyz;
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float l1 = float(TFC_LAMBDA_MIN_NM) + float(b) * width;
    float l2 = l1 + width;
    float center = 0.5 * (l1 + l2);
    DispersiveBin d = tfcDispersiveBin(row, b, thicknessNm, fromInside, cosIncidence);
    float low = d.pathPerNmLow * thicknessNm / l1;
    float high = d.pathPerNmHigh * thicknessNm / l2;
    // φ at the two ends, linear in σ between them, over the light's window in σ (tfcBinnedXyz's).
    float slope = 6.283185307179586 * (low - high) / (1.0 / l1 - 1.0 / l2);
    vec2 spread = texelFetch(uSpectralBins, ivec2(b, 1), 0).xy;
    xyz += tfcBinReflectance(d.optics, center, 3.141592653589793 * (low + high) + slope * spread.x, abs(slope) * spread.y) * tfcBinWeight(b);
  }
  return xyz;
}
#endif

#endif

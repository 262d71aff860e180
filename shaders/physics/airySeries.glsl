// The film's XYZ from the Airy sum as a Fourier series in the phase, eqs (11)-(18):
//   X_j = C0 W_j + 2 Re( B sum_{m>=1} q^(m-1) F_j(m x) ),  x = 2 n_b d cos θ_r (eq 12),
// with C0, B, q from one channel's Fresnel terms and F_j the light's spectral transform, a table
// (uSpectralTransform) of H_j(x) = F_j(x) e^{-i2πσ0 x} every TFC_SPECTRAL_TRANSFORM_STEP_NM of x:
// rows 0 .. TFC_SPECTRAL_TRANSFORM_ROWS-1 hold Re H (xyz), the next TFC_SPECTRAL_TRANSFORM_ROWS rows Im H.
// Domain: a real optical path (not an evanescent film). Mirrors src/physics/airySeries.ts; the
// derivation is in docs/physics.md.
// airySeriesConvergesAt and airySeriesSum take the terms, computed once by the caller (per
// fragment from the optics, or per table row from uAirySeriesRows); their TypeScript twins,
// airySeriesConverges and airySeriesXyz, take the optics.
#ifndef THIN_FILM_AIRY_SERIES
#define THIN_FILM_AIRY_SERIES
#include "filmReflectance.glsl"
#include "environmentMatrix.glsl"

// The truncation rule of airySeriesXyz (TypeScript): stop when the terms left are below
// TFC_AIRY_SERIES_TOLERANCE of the white, when F runs off its table, or at TFC_AIRY_SERIES_MAX_ORDERS;
// airySeriesConverges says whether the first two come before the last.
#ifndef TFC_AIRY_SERIES_MAX_ORDERS
#define TFC_AIRY_SERIES_MAX_ORDERS 128
#endif
#ifndef TFC_AIRY_SERIES_TOLERANCE
#define TFC_AIRY_SERIES_TOLERANCE 1e-5
#endif
// 1: the series cut at TFC_AIRY_SERIES_MAX_ORDERS as peers do (the benchmark's m <= 2, m <= 3 rows).
#ifndef TFC_AIRY_SERIES_TRUNCATED
#define TFC_AIRY_SERIES_TRUNCATED 0
#endif

uniform sampler2D uSpectralTransform;

struct AirySeriesTerms { float c0; vec2 b; vec2 q; };

AirySeriesTerms tfcAirySeriesTerms(AiryTerms c) {
  float rab2 = tfcCAbs2(c.rab);
  if (c.multiple == vec2(0.0)) return AirySeriesTerms(rab2, vec2(0.0), vec2(0.0));
  float g = tfcCAbs2(c.multiple) / (1.0 - tfcCAbs2(c.roundTrip));
  return AirySeriesTerms(rab2 + g, tfcCMul(c.multiple, vec2(c.rab.x, -c.rab.y)) + g * c.roundTrip, c.roundTrip);
}

// H at texel p of each plane (TFC_ENVIRONMENT_MATRIX: the transforms of the light times each basis
// spectrum, one above the other, 2 TFC_SPECTRAL_TRANSFORM_ROWS rows each), as the film's colour
// (environmentMatrix.glsl): a vec3, or a mat3 of plane j's in column j.
TFC_FILM_COLOR tfcTransformTexel(ivec2 p) {
#ifdef TFC_ENVIRONMENT_MATRIX
  ivec2 plane = ivec2(0, 2 * TFC_SPECTRAL_TRANSFORM_ROWS);
  return mat3(texelFetch(uSpectralTransform, p, 0).xyz, texelFetch(uSpectralTransform, p + plane, 0).xyz, texelFetch(uSpectralTransform, p + 2 * plane, 0).xyz);
#else
  return texelFetch(uSpectralTransform, p, 0).xyz;
#endif
}

// H at entry i, real and imaginary parts.
void tfcTransformEntry(int i, out TFC_FILM_COLOR re, out TFC_FILM_COLOR im) {
  ivec2 p = ivec2(i % TFC_SPECTRAL_TRANSFORM_WIDTH, i / TFC_SPECTRAL_TRANSFORM_WIDTH);
  re = tfcTransformTexel(p);
  im = tfcTransformTexel(p + ivec2(0, TFC_SPECTRAL_TRANSFORM_ROWS));
}

// The carrier e^{i2πσ0 x}, its phase reduced to turns before the 2π so float32 keeps its digits.
vec2 tfcTransformCarrier(float pathNm) {
  return tfcCExpI(vec2(6.283185307179586 * fract(float(TFC_SPECTRAL_TRANSFORM_CARRIER_PER_NM) * pathNm), 0.0));
}

// F(x) = H(x) carrier, H linear between entries; false past the table (F taken as 0).
bool tfcTransformAt(float pathNm, vec2 carrier, out TFC_FILM_COLOR re, out TFC_FILM_COLOR im) {
  float pos = pathNm / float(TFC_SPECTRAL_TRANSFORM_STEP_NM);
  float first = floor(pos);
  if (first >= float(TFC_SPECTRAL_TRANSFORM_COUNT - 1)) return false;
  int i = int(first);
  TFC_FILM_COLOR re0, im0, re1, im1;
  tfcTransformEntry(i, re0, im0);
  tfcTransformEntry(i + 1, re1, im1);
  float f = pos - first;
  TFC_FILM_COLOR hr = re0 + f * (re1 - re0);
  TFC_FILM_COLOR hi = im0 + f * (im1 - im0);
  re = hr * carrier.x - hi * carrier.y;
  im = hr * carrier.y + hi * carrier.x;
  return true;
}

// |B| / (1 - |q|): with |q|^(m-1), a bound on the terms from order m on (|F| <= W).
float tfcAirySeriesTailScale(AirySeriesTerms t) {
  return length(t.b) / max(1.0 - length(t.q), 1e-7);
}

// Whether TFC_AIRY_SERIES_MAX_ORDERS terms reach the tolerance or the end of F's table at path x. They
// do not for high-finesse thin films near grazing incidence (|q| -> 1): callers integrate those by bins.
bool tfcAirySeriesConvergesAt(AirySeriesTerms t[TFC_FILM_CHANNELS], float x) {
  float orders = float(TFC_AIRY_SERIES_MAX_ORDERS);
  if (x * orders >= float(TFC_SPECTRAL_TRANSFORM_STEP_NM) * float(TFC_SPECTRAL_TRANSFORM_COUNT - 1)) return true;
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) {
    float scale = tfcAirySeriesTailScale(t[c]);
    float rho = length(t[c].q);
    if (scale >= TFC_AIRY_SERIES_TOLERANCE && (rho >= 1.0 || (orders - 1.0) * log(rho) > log(TFC_AIRY_SERIES_TOLERANCE / scale))) return false;
  }
  return true;
}

// X_j = C0 W_j + 2 Re(B sum q^(m-1) F_j(m x)), averaged over the channels.
TFC_FILM_COLOR tfcAirySeriesSum(AirySeriesTerms t[TFC_FILM_CHANNELS], float x) {
  TFC_FILM_COLOR sumRe[TFC_FILM_CHANNELS];
  TFC_FILM_COLOR sumIm[TFC_FILM_CHANNELS];
  vec2 power[TFC_FILM_CHANNELS];
  float powerAbs[TFC_FILM_CHANNELS];
  float rho[TFC_FILM_CHANNELS];
  float leftScale[TFC_FILM_CHANNELS];
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) {
    sumRe[c] = TFC_FILM_COLOR(0.0);
    sumIm[c] = TFC_FILM_COLOR(0.0);
    power[c] = vec2(1.0, 0.0);
    powerAbs[c] = 1.0;
    rho[c] = length(t[c].q);
    leftScale[c] = tfcAirySeriesTailScale(t[c]);
  }
  // The carrier of order m is the first one's m-th power (a product per order, not a sine).
  vec2 step = tfcTransformCarrier(x);
  vec2 carrier = step;
  for (int m = 1; m <= TFC_AIRY_SERIES_MAX_ORDERS; m++) {
    float left = 0.0;
    for (int c = 0; c < TFC_FILM_CHANNELS; c++) left = max(left, leftScale[c] * powerAbs[c]);
    if (left < TFC_AIRY_SERIES_TOLERANCE) break;
    TFC_FILM_COLOR fr, fi;
    if (!tfcTransformAt(float(m) * x, carrier, fr, fi)) break;
    carrier = tfcCMul(carrier, step);
    for (int c = 0; c < TFC_FILM_CHANNELS; c++) {
      sumRe[c] += power[c].x * fr - power[c].y * fi;
      sumIm[c] += power[c].x * fi + power[c].y * fr;
      power[c] = tfcCMul(power[c], t[c].q);
      powerAbs[c] *= rho[c];
    }
  }
  TFC_FILM_COLOR white = tfcTransformTexel(ivec2(0));
  TFC_FILM_COLOR xyz = TFC_FILM_COLOR(0.0);
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) xyz += t[c].c0 * white + 2.0 * (t[c].b.x * sumRe[c] - t[c].b.y * sumIm[c]);
  return xyz / float(TFC_FILM_CHANNELS);
}

void tfcAirySeriesTermsOf(FilmOptics o, out AirySeriesTerms t[TFC_FILM_CHANNELS]) {
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) t[c] = tfcAirySeriesTerms(o.channels[c]);
}

#endif

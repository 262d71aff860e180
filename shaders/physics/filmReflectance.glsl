// Film reflectance by the Airy sum, eqs (1)-(14), and its closed-form mean over a phase window.
// Mirrors src/physics/filmReflectance.ts. Defines:
//   TFC_POLARIZATION  TFC_POLARIZATION_UNPOLARIZED (R_s + R_p)/2 | _PAPER (eqs 4, 8: amplitudes
//     averaged) | _S | _P, codes from src/gpu/enumDefines.ts
//   TFC_POLARIZATION_UNIFORM  1: the polarisation is the uniform uPolarization (the same codes) and
//     there are always two channels (a single polarisation twice): one program for every polarisation.
//   Sets TFC_FILM_CHANNELS (1 or 2) and, for two, TFC_BOTH_CHANNELS.
#ifndef THIN_FILM_REFLECTANCE
#define THIN_FILM_REFLECTANCE
#include "complex.glsl"
#include "snell.glsl"
#include "fresnel.glsl"

#ifndef TFC_POLARIZATION
#define TFC_POLARIZATION TFC_POLARIZATION_UNPOLARIZED
#endif
#if TFC_POLARIZATION == TFC_POLARIZATION_UNPOLARIZED || defined(TFC_POLARIZATION_UNIFORM)
#define TFC_BOTH_CHANNELS
#define TFC_FILM_CHANNELS 2
#else
#define TFC_FILM_CHANNELS 1
#endif
#ifdef TFC_POLARIZATION_UNIFORM
uniform int uPolarization;
#endif

// The λ-independent factors of eq (13) for one channel:
// r = r_ab + multiple e^{iφ} / (1 - roundTrip e^{iφ}), multiple = t_ab t_ba r_bc, roundTrip = r_ba r_bc.
struct AiryTerms { vec2 rab; vec2 multiple; vec2 roundTrip; };

struct FilmOptics {
  AiryTerms channels[TFC_FILM_CHANNELS];
  // Δ = 2 ñ_b d cos θ_r (eq 12 reduced), complex past the critical angle or in an absorbing film
  vec2 opticalPathNm;
};

// (r, t) of one interface for channel kind 0 = s, 1 = p, 2 = the paper's average (eqs 4, 8).
vec4 tfcChannelOf(InterfaceCoefficients c, int kind) {
  if (kind == 0) return vec4(c.rs, c.ts);
  if (kind == 1) return vec4(c.rp, c.tp);
  return 0.5 * vec4(c.rs + c.rp, c.ts + c.tp);
}

AiryTerms tfcAiryTerms(InterfaceCoefficients ab, InterfaceCoefficients ba, InterfaceCoefficients bc, int kind) {
  vec4 a = tfcChannelOf(ab, kind);
  vec4 b = tfcChannelOf(ba, kind);
  vec4 c = tfcChannelOf(bc, kind);
  return AiryTerms(a.xy, tfcCMul(tfcCMul(a.zw, b.zw), c.xy), tfcCMul(b.xy, c.xy));
}

int tfcChannelKind(int i) {
#ifdef TFC_POLARIZATION_UNIFORM
  int polarization = uPolarization;
#else
  int polarization = TFC_POLARIZATION;
#endif
  if (polarization == TFC_POLARIZATION_UNPOLARIZED) return i;
  if (polarization == TFC_POLARIZATION_PAPER) return 2;
  return polarization == TFC_POLARIZATION_S ? 0 : 1;
}

// Re Δ per nm of thickness for light from n_a: Re(2 ñ_b cos θ_r) (eq 12 reduced), 0 for an evanescent film.
float tfcFilmPathPerNm(vec2 nFilm, float nOutside, float cosIncidence) {
  return 2.0 * tfcCMul(nFilm, tfcRefractedCos(nFilm, nOutside, cosIncidence)).x;
}

// The outside is transparent (a real n_a); the film and the inside are ñ = vec2(n, k).
FilmOptics tfcFilmOptics(float nOutside, vec2 nFilm, vec2 nInside, float thicknessNm, float cosIncidence) {
  vec2 na = vec2(nOutside, 0.0);
  vec2 cosI = tfcRefractedCos(nOutside, nOutside, cosIncidence);
  vec2 cosR = tfcRefractedCos(nFilm, nOutside, cosIncidence);
  vec2 cosT = tfcRefractedCos(nInside, nOutside, cosIncidence);
  FilmOptics o;
  o.opticalPathNm = 2.0 * thicknessNm * tfcCMul(nFilm, cosR);
  InterfaceCoefficients ab = tfcFresnelCoefficients(na, cosI, nFilm, cosR);
  InterfaceCoefficients ba = tfcFresnelCoefficients(nFilm, cosR, na, cosI);
  InterfaceCoefficients bc = tfcFresnelCoefficients(nFilm, cosR, nInside, cosT);
  for (int i = 0; i < TFC_FILM_CHANNELS; i++) o.channels[i] = tfcAiryTerms(ab, ba, bc, tfcChannelKind(i));
  if (thicknessNm == 0.0) {
    // At d = 0 the physical channels (s, p) are the bare a|c interface, eq (13)'s own value there
    // (the Stokes relations) and its limit at grazing; the paper's channel keeps eq (13). See
    // bareInterface in the TypeScript twin.
    InterfaceCoefficients ac = tfcFresnelCoefficients(na, cosI, nInside, cosT);
    for (int i = 0; i < TFC_FILM_CHANNELS; i++) {
      int kind = tfcChannelKind(i);
      if (kind != 2) o.channels[i] = AiryTerms(tfcChannelOf(ac, kind).xy, vec2(0.0), vec2(0.0));
    }
  }
  return o;
}

// One channel's R, eq (13) squared, at the round-trip phase factor z = e^{iφ}.
float tfcChannelReflectance(AiryTerms c, vec2 z) {
  vec2 series = (c.multiple == vec2(0.0)) ? vec2(0.0) : tfcCDiv(tfcCMul(c.multiple, z), vec2(1.0, 0.0) - tfcCMul(c.roundTrip, z));
  return tfcCAbs2(c.rab + series);
}

// R at one wavelength, eqs (11), (13), (14), averaged over the channels.
float tfcReflectanceAt(FilmOptics o, float lambdaNm) {
  vec2 z = tfcCExpI(o.opticalPathNm * (6.283185307179586 / lambdaNm));
  float sum = 0.0;
  for (int i = 0; i < TFC_FILM_CHANNELS; i++) sum += tfcChannelReflectance(o.channels[i], z);
  return min(1.0, sum / float(TFC_FILM_CHANNELS));
}

// The mean of one channel's R over phases [φ0 - w, φ0 + w] in closed form; the derivation is in
// src/physics/filmReflectance.ts (meanChannelReflectance).
float tfcMeanChannelReflectance(AiryTerms c, float phaseCenter, float halfWidth) {
  vec2 alpha = c.rab;
  vec2 beta = c.multiple - tfcCMul(c.rab, c.roundTrip);
  float a0 = tfcCAbs2(alpha) + tfcCAbs2(beta);
  vec2 ab = tfcCMul(vec2(alpha.x, -alpha.y), beta);
  float rho2 = tfcCAbs2(c.roundTrip);
  float w = halfWidth;
  float sinc = w == 0.0 ? 1.0 : sin(w) / w;
  if (c.multiple == vec2(0.0)) return tfcCAbs2(alpha);
  if (rho2 == 0.0) return a0 + 2.0 * sinc * (ab.x * cos(phaseCenter) - ab.y * sin(phaseCenter));
  float rho = sqrt(rho2);
  // float32 guard (not in the float64 twin): near an Airy resonance with |r_ba r_bc| → 1 (grazing
  // light) the closed form below is a difference of terms ~1/(1 − ρ) that cancel to R(1 − ρ²),
  // and float32 keeps too few digits of it, visibly so for sub-nanometre films near grazing light
  // (docs/gpu.md#float32-limits). A window narrower than the resonance (w < (1 − ρ)/2) is averaged
  // by Simpson's rule on eq (13) itself, which has no such cancellation; its error is
  // ~(w / (1 − ρ))⁴ / 180 ≤ 4e-4 of R.
  if (w < 0.5 * (1.0 - rho)) {
    return clamp((tfcChannelReflectance(c, tfcCExpI(vec2(phaseCenter - w, 0.0))) + 4.0 * tfcChannelReflectance(c, tfcCExpI(vec2(phaseCenter, 0.0)))
      + tfcChannelReflectance(c, tfcCExpI(vec2(phaseCenter + w, 0.0)))) / 6.0, 0.0, 1.0);
  }
  // arg(c), with Im c = -0.0 read as 0: GLSL need not honour signed zeros, and SwiftShader's
  // atan(-0.0, x) returns pi for x > 0, which shifts the p channel's fringes by half a period.
  float gamma = c.roundTrip.y == 0.0 ? (c.roundTrip.x < 0.0 ? 3.141592653589793 : 0.0) : atan(c.roundTrip.y, c.roundTrip.x);
  float psi0 = phaseCenter + gamma;
  vec2 u = tfcCDiv(ab, c.roundTrip);
  float cosW = cos(w), cos0 = cos(psi0), sin0 = sin(psi0);
  float y = 2.0 * rho * sinc * (cos0 - rho * cosW);
  float x = 1.0 - 2.0 * rho * cos0 * cosW + rho2 * cos(2.0 * w);
  float dA = w < 1e-4 ? y / x : atan(y * w, x) / w;
  float dPlus = 1.0 + rho2 - 2.0 * rho * cos(psi0 + w);
  float dMinus = 1.0 + rho2 - 2.0 * rho * cos(psi0 - w);
  float qOverW = 4.0 * rho * sin0 * sinc / (dPlus + dMinus);
  float q = qOverW * w;
  // Below |q| = 1e-3, atanh(q)/q = 1 + q^2/3 to 2e-13, as in the TypeScript twin.
  float L = abs(q) < 1e-3 ? qOverW * (1.0 + q * q / 3.0) : atanh(q) / q * qOverW;
  float mean = (a0 * (1.0 + dA) + u.x * (2.0 * rho2 + (1.0 + rho2) * dA)) / (1.0 - rho2) - u.y * L;
  return clamp(mean, 0.0, 1.0);
}

#endif

// Snell's law, eqs (1), (2): cos θ_j in a medium of index n, complex past the critical angle
// (Im >= 0: the evanescent wave decays). n cos θ_j = sqrt((n - n_a)(n + n_a) + (n_a cos θ_i)^2).
// An absorbing medium ñ = n + ik (vec2(n, k), k > 0) takes the same root in complex arithmetic on the
// branch Im(ñ cos θ_j) >= 0, where the wave decays into it; k = 0 is the real path.
// Mirrors src/physics/snell.ts.
#ifndef THIN_FILM_SNELL
#define THIN_FILM_SNELL
#include "complex.glsl"

vec2 tfcRefractedCos(float n, float nOutside, float cosIncidence) {
  float nCosIncidence = nOutside * cosIncidence;
  float nCos2 = (n - nOutside) * (n + nOutside) + nCosIncidence * nCosIncidence;
  return nCos2 >= 0.0 ? vec2(sqrt(nCos2) / n, 0.0) : vec2(0.0, sqrt(-nCos2) / n);
}

vec2 tfcRefractedCos(vec2 n, float nOutside, float cosIncidence) {
  if (n.y == 0.0) return tfcRefractedCos(n.x, nOutside, cosIncidence);
  float nCosIncidence = nOutside * cosIncidence;
  vec2 square = tfcCMul(n - vec2(nOutside, 0.0), n + vec2(nOutside, 0.0)) + vec2(nCosIncidence * nCosIncidence, 0.0);
  vec2 root = tfcCSqrt(square);
  return tfcCDiv(root.y < 0.0 ? -root : root, n);
}

#endif

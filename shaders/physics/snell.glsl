// Snell's law, eqs (1), (2): cos θ_j in a medium of index n, complex past the critical angle
// (Im >= 0: the evanescent wave decays). n cos θ_j = sqrt((n - n_a)(n + n_a) + (n_a cos θ_i)^2).
// Mirrors src/physics/snell.ts.
#ifndef THIN_FILM_SNELL
#define THIN_FILM_SNELL

vec2 tfcRefractedCos(float n, float nOutside, float cosIncidence) {
  float nCosIncidence = nOutside * cosIncidence;
  float nCos2 = (n - nOutside) * (n + nOutside) + nCosIncidence * nCosIncidence;
  return nCos2 >= 0.0 ? vec2(sqrt(nCos2) / n, 0.0) : vec2(0.0, sqrt(-nCos2) / n);
}

#endif

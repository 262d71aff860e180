// The film's index n_b(λ) of a dispersive film (TFC_DISPERSIVE): uFilmIndexKnots holds n_b at
// TFC_FILM_INDEX_KNOTS wavelengths every TFC_FILM_INDEX_STEP_NM from TFC_FILM_INDEX_FIRST_NM,
// four to a vec4, computed in float64 by src/physics/filmIndex.ts (filmIndexAt) and taken as linear
// between knots. Mirrors filmIndexAt; set by src/film/filmIndexUniforms.ts.
#ifndef THIN_FILM_INDEX
#define THIN_FILM_INDEX
#include "snell.glsl"

uniform vec4 uFilmIndexKnots[(TFC_FILM_INDEX_KNOTS + 3) / 4];

float tfcFilmIndexKnot(int i) { return uFilmIndexKnots[i / 4][i % 4]; }

float tfcFilmIndexAt(float lambdaNm) {
  float pos = clamp((lambdaNm - float(TFC_FILM_INDEX_FIRST_NM)) / float(TFC_FILM_INDEX_STEP_NM), 0.0, float(TFC_FILM_INDEX_KNOTS - 1));
  int i = min(int(pos), TFC_FILM_INDEX_KNOTS - 2);
  return mix(tfcFilmIndexKnot(i), tfcFilmIndexKnot(i + 1), pos - float(i));
}

// Re Δ per nm of thickness at λ: 2 n_b(λ) Re cos θ_r(λ) (eq 12 reduced), 0 for an evanescent film.
float tfcFilmPathPerNm(float lambdaNm, float nOutside, float cosIncidence) {
  float nb = tfcFilmIndexAt(lambdaNm);
  return 2.0 * nb * tfcRefractedCos(nb, nOutside, cosIncidence).x;
}

#endif

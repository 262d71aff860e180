// A film drained by gravity: thin at the top, thick at the bottom, linear in the height h
// (clamped to ±1) about the mean, down to a ~10 nm black film in a cap around the top (y: the
// point's own height). Mirrors src/fields/drainedFilm.ts.
#ifndef THIN_FILM_DRAINED_FILM
#define THIN_FILM_DRAINED_FILM
uniform float uThicknessNm;
uniform float uThicknessRangeNm;

float tfcDrainedThicknessNm(float h, float y) {
  float d = uThicknessNm - 0.5 * uThicknessRangeNm * clamp(h, -1.0, 1.0);
  d = mix(max(d, 10.0), 10.0, smoothstep(0.82, 0.95, y));
  return clamp(d, 0.0, 20000.0);
}
#endif

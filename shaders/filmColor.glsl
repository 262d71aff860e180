// The film's XYZ at a thickness and cos θ_i, by the method FILM_MODE selects:
//   0 exact: the binned spectral integral per fragment;  1 table: one filtered lookup.
// fromInside swaps the outer and inner media (the far wall seen through the bubble).
#ifndef THIN_FILM_COLOR
#define THIN_FILM_COLOR

#if FILM_MODE == 0
#include "spectralIntegration.glsl"
uniform float uNOutside;
uniform float uNFilm;
uniform float uNInside;

vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  float na = fromInside ? uNInside : uNOutside;
  float nc = fromInside ? uNOutside : uNInside;
  return binnedXyz(filmOptics(na, uNFilm, nc, thicknessNm, cosIncidence), 0.0);
}
#else
uniform sampler2D uFilmTable;
uniform float uTableMaxThicknessNm;

vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  // Texel centres sit at the ends of the ranges (BROWSER.md: otherwise visibly off).
  float u = clamp(thicknessNm / uTableMaxThicknessNm, 0.0, 1.0);
  float v = clamp(cosIncidence, 0.0, 1.0);
  vec2 size = vec2(float(FILM_TABLE_WIDTH), float(2 * FILM_TABLE_ROWS));
  float rowOffset = fromInside ? float(FILM_TABLE_ROWS) : 0.0;
  vec2 texel = vec2(u * float(FILM_TABLE_WIDTH - 1), rowOffset + v * float(FILM_TABLE_ROWS - 1)) + 0.5;
  return texture(uFilmTable, texel / size).xyz;
}
#endif

#endif

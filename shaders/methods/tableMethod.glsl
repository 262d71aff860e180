// `table` (src/methods/tableMethod.ts): the film's XYZ as one filtered lookup in the film table
// (src/film/filmTable.ts builds it; filmTableLayout.glsl maps thickness and cos θ to its grid).
#ifndef THIN_FILM_TABLE_METHOD
#define THIN_FILM_TABLE_METHOD

#include "filmTableGrid.glsl"
#include "filmTableLayout.glsl"
uniform sampler2D uFilmTable;

vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
  // Texel centres sit at the ends of the ranges (docs/gpu.md#texel-centres: otherwise visibly off).
  vec2 uv = tfcFilmTableUv(thicknessNm, cosIncidence, uTableMaxThicknessNm);
  // The grid may fill only the texture's lower left corner (a coarse table, FilmTable).
  vec2 size = vec2(textureSize(uFilmTable, 0));
  float rowOffset = fromInside ? uFilmTableRows : 0.0;
  vec2 texel = vec2(uv.x * (uFilmTableWidth - 1.0), rowOffset + uv.y * (uFilmTableRows - 1.0)) + 0.5;
  return texture(uFilmTable, texel / size).xyz;
}

#endif

// `table` (src/methods/tableMethod.ts): the film's XYZ as one filtered lookup in the film table (its
// environment matrix as three, one in each of the table's planes, with TFC_ENVIRONMENT_MATRIX)
// (src/film/filmTable.ts builds it; filmTableLayout.glsl maps thickness and cos θ to its grid).
#ifndef THIN_FILM_TABLE_METHOD
#define THIN_FILM_TABLE_METHOD

#include "filmTableGrid.glsl"
#include "filmTableLayout.glsl"
uniform sampler2D uFilmTable;
#ifdef TFC_ENVIRONMENT_MATRIX
uniform sampler2D uFilmTable1;
uniform sampler2D uFilmTable2;
#endif

TFC_FILM_COLOR tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
  // Texel centres sit at the ends of the ranges (docs/gpu.md#texel-centres: otherwise visibly off).
  vec2 uv = tfcFilmTableUv(thicknessNm, cosIncidence, uTableMaxThicknessNm);
  // The grid may fill only the texture's lower left corner (a coarse table, FilmTable).
  vec2 size = vec2(textureSize(uFilmTable, 0));
  float rowOffset = fromInside ? uFilmTableRows : 0.0;
  vec2 texel = vec2(uv.x * (uFilmTableWidth - 1.0), rowOffset + uv.y * (uFilmTableRows - 1.0)) + 0.5;
#ifdef TFC_ENVIRONMENT_MATRIX
  // Plane j, the film under the light times basis spectrum j, in its own texture: M's columns.
  return mat3(texture(uFilmTable, texel / size).xyz, texture(uFilmTable1, texel / size).xyz, texture(uFilmTable2, texel / size).xyz);
#else
  return texture(uFilmTable, texel / size).xyz;
#endif
}

#endif

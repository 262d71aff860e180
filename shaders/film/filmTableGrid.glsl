// The grid the film table holds (src/film/filmTableGrid.ts, filmTableGridUniforms): texels along
// thickness, rows per half, and the thickness of its last column. FilmTable may hold a coarse grid
// for a frame, in the lower left corner of its texture. Where a film sits in it: filmTableLayout.glsl.
// Declared here once for the table pass (filmTable.glsl) and the lookup (the `table` method).
#ifndef THIN_FILM_TABLE_GRID
#define THIN_FILM_TABLE_GRID
uniform float uFilmTableWidth;
uniform float uFilmTableRows;
uniform float uTableMaxThicknessNm;
#endif

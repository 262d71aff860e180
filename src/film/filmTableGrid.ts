import type { ShaderMaterial, Texture } from 'three';

/**
 * The grid a film table holds (shaders/film/filmTableGrid.glsl): texels along thickness, rows per
 * half, and the thickness of its last column. The table pass draws it and the lookup reads it; a
 * coarse table holds a smaller grid in the texture's lower left corner.
 */
export interface FilmTableGrid {
  readonly width: number;
  readonly rows: number;
  readonly maxThicknessNm: number;
}

/** The uniforms filmTableGrid.glsl declares, for the table pass and for every shader that looks the table up. */
export const filmTableGridUniforms = () => ({
  uTableMaxThicknessNm: { value: 1 },
  uFilmTableWidth: { value: 1 },
  uFilmTableRows: { value: 1 },
});

/** Sets filmTableGridUniforms to `grid`. */
export function setFilmTableGridUniforms(u: ShaderMaterial['uniforms'], grid: FilmTableGrid): void {
  u.uTableMaxThicknessNm!.value = grid.maxThicknessNm;
  u.uFilmTableWidth!.value = grid.width;
  u.uFilmTableRows!.value = grid.rows;
}

/** Points a material that looks a table up (the `table` method) at `table`, which holds `grid`. */
export function bindFilmTable(u: ShaderMaterial['uniforms'], table: Texture, grid: FilmTableGrid): void {
  u.uFilmTable!.value = table;
  setFilmTableGridUniforms(u, grid);
}

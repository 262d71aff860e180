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

/** The uniforms of a shader that looks the table up (shaders/methods/tableMethod.glsl): its texture and its grid. */
export const filmTableUniforms = () => ({
  uFilmTable: { value: null as Texture | null },
  ...filmTableGridUniforms(),
});

/** The textures of a table's second and third colour planes, for a shader that may look up a film's environment matrix (the bubble's). */
export const filmTablePlanesUniforms = () => ({
  uFilmTable1: { value: null as Texture | null },
  uFilmTable2: { value: null as Texture | null },
});

/**
 * Points a material that looks a table up (the `table` method) at `planes`, the table's colour
 * planes (one, or three: shaders/methods/tableMethod.glsl), which hold `grid`.
 */
export function bindFilmTable(u: ShaderMaterial['uniforms'], planes: readonly Texture[], grid: FilmTableGrid): void {
  u.uFilmTable!.value = planes[0];
  if (planes.length === 3) [u.uFilmTable1!.value, u.uFilmTable2!.value] = planes.slice(1);
  setFilmTableGridUniforms(u, grid);
}

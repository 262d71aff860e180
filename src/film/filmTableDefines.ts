import { enumDefines } from '../gpu/enumDefines.ts';
import { type FilmTableLayout, TABLE_FILLS } from '../settings/filmTableLayout.ts';

/**
 * The defines shaders/film/filmTableLayout.glsl and filmTable.glsl read: the layout's powers and
 * fill (its grid is uniforms, filmTableGrid.ts: the width follows the thickness range, and a coarse
 * table has fewer texels).
 */
export const filmTableLayoutDefines = (l: FilmTableLayout): Record<string, number> => ({
  TFC_FILM_TABLE_THICKNESS_POWER: l.thicknessPower,
  TFC_FILM_TABLE_COS_POWER: l.cosPower,
  ...enumDefines('TFC_TABLE_FILL', TABLE_FILLS, l.fill),
});

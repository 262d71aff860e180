import type { FilmOptics } from '../settings/filmSettings.ts';
import { followsField } from '../physics/stackFilms.ts';
import { filmLayersOf } from '../methods/filmStacks.ts';
import type { StackedSettings } from './filmStack.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { planesLight } from '../physics/spectralWeights.ts';

/**
 * What the table of `s` over thicknesses up to `maxThicknessNm` (the field's range) depends on;
 * anything else (the field's animation, exposure, space) leaves it alone: a stack of films in place
 * of nFilm, the range only where the film follows the field, its colour planes (filmPlanes:
 * which environment, as long as one is coloured, does not matter) and the light they are computed
 * under (planesLight: in three planes, not the tint). Apart from filmTable.ts, so that
 * the node material's table (src/nodeMaterial/filmTable.ts) keys its table alike without the GLSL passes.
 */
export function tableKey(s: FilmOptics & StackedSettings, maxThicknessNm: number): string {
  const films = filmLayersOf(s);
  const range = followsField(films) ? maxThicknessNm : null;
  const planes = filmPlanes(s);
  const { lightTint } = planesLight(s, planes);
  return JSON.stringify([s.nOutside, films, s.nInside, s.illuminant, lightTint, s.polarization, s.normalization, range, planes]);
}

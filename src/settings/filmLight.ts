import { WHITE_TINT, isWhiteTint } from '../physics/lightTint.ts';
import type { PlaneCount } from '../physics/spectralWeights.ts';
import { environmentKind } from '../environments/environments.ts';
import type { FilmOptics, FilmSettings } from './filmSettings.ts';

/**
 * The light and colour a film is seen in unless asked otherwise: the schema's defaults
 * (filmParameters.ts) and a material's (meshMaterial/), which reads them without the schema.
 */
export const DEFAULT_LIGHT = {
  illuminant: 'D65',
  lightTint: WHITE_TINT,
  polarization: 'unpolarized',
  normalization: 'white',
} as const satisfies Pick<FilmSettings, 'illuminant' | 'lightTint' | 'polarization' | 'normalization'>;

/**
 * The colour planes a film is computed in: 3, its environment matrix M (physics/environmentMatrix.ts),
 * where it reflects a coloured environment or a tinted light, so that each colour it reflects is an
 * integral of two spectra and a tint is a colour M maps (a change of tint changes no plane); 1, its
 * XYZ under the light, where it reflects only the untinted light's white (`env=none`). A material's
 * film (no `env`) has three where its scene has an environment (`sceneEnvironment`: three's
 * scene.environment or the material's envMap), whose light it reflects through M, and one otherwise,
 * computed under the tinted light.
 */
export const filmPlanes = (s: Partial<Pick<FilmSettings, 'env' | 'lightTint'> & Pick<FilmOptics, 'sceneEnvironment'>>): PlaneCount => {
  if (s.env === undefined) return s.sceneEnvironment === true ? 3 : 1;
  return environmentKind(s.env) === 'none' && isWhiteTint(s.lightTint ?? WHITE_TINT) ? 1 : 3;
};

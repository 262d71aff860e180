import { WHITE_TINT } from '../physics/lightTint.ts';
import type { PlaneCount } from '../physics/spectralWeights.ts';
import { environmentKind } from '../environments/environments.ts';
import type { FilmSettings } from './filmSettings.ts';

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
 * where it reflects a coloured environment, so that each colour it reflects is an integral of two
 * spectra; 1, its XYZ under the light, where it reflects only the light's white (`env=none`, or no
 * environment named: a material).
 */
export const filmPlanes = (s: Partial<Pick<FilmSettings, 'env'>>): PlaneCount =>
  s.env === undefined || environmentKind(s.env) === 'none' ? 1 : 3;

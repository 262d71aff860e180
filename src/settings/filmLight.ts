import { WHITE_TINT } from '../physics/lightTint.ts';
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

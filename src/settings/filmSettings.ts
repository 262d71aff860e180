import { type Medium } from '../physics/medium.ts';
import type { FilmLayer } from '../physics/stackFilms.ts';
import { FIELDS, type FieldName, type FieldSettings } from '../fields/fields.ts';
import { ENVIRONMENTS, type Environment, HDR_ENVIRONMENTS, type HdrEnvironment, isHdrEnvironment } from '../environments/environments.ts';
import { FILM_METHODS, type FilmMethodName, MODES } from '../methods/methods.ts';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import type { LightTint } from '../physics/lightTint.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type Normalization } from '../physics/spectralWeights.ts';

export const SPACES = ['srgb', 'display-p3', 'wide-gamut'] as const;
/** How the film colour is computed (`mode`): the methods' registry, src/methods/methods.ts. */
export { FIELDS, FILM_METHODS, MODES };
export const SIDES = ['both', 'front'] as const;
export { ENVIRONMENTS, HDR_ENVIRONMENTS, isHdrEnvironment };
export type { Environment, HdrEnvironment };
/**
 * How HDR light becomes display values: `none` clips (the reference views stay exact), `agx` and
 * `neutral` are three.js's AgX and Khronos PBR Neutral curves; `auto` is `none` for `none`, `sky`
 * and a uniform colour (at most four times the light's white: no curve bends the film's reflection of
 * that one known light, and only a background brighter than white clips), `agx` for the HDR
 * environments (so the sun and bright windows keep their highlights).
 */
export const TONE_MAPPINGS = ['auto', 'none', 'agx', 'neutral'] as const;
export type ToneMapping = Exclude<(typeof TONE_MAPPINGS)[number], 'auto'>;

/** The tone mapping a view uses (see TONE_MAPPINGS). */
export const toneMappingOf = (s: Pick<FilmSettings, 'tonemap' | 'env'>): ToneMapping =>
  s.tonemap !== 'auto' ? s.tonemap : isHdrEnvironment(s.env) ? 'agx' : 'none';

/**
 * Everything a rendered bubble depends on, the fields' settings (each field's own, declared by the
 * field) included. Ranges and defaults: the schema, `filmParameters.ts`.
 */
export interface FilmSettings extends FieldSettings {
  readonly nOutside: number;
  /** ñ_b: a number, a material, a Cauchy film, a named medium or a complex constant (medium.ts) */
  readonly nFilm: Medium;
  /**
   * A stack of films from the outside in (stackFilms.ts), in place of the single film of `nFilm`
   * and `thicknessNm`; a layer of FIELD_THICKNESS takes the thickness field's value. Empty: the single film.
   */
  readonly layers: readonly FilmLayer[];
  /** ñ_c, the same kinds: an absorbing one (a metal) is opaque */
  readonly nInside: Medium;
  readonly illuminant: IlluminantSpec;
  /** The light's tint, linear sRGB relative to its white (lightTint.ts). */
  readonly lightTint: LightTint;
  readonly polarization: Polarization;
  readonly normalization: Normalization;
  readonly space: (typeof SPACES)[number];
  readonly mode: FilmMethodName;
  readonly field: FieldName;
  readonly sides: (typeof SIDES)[number];
  readonly env: Environment;
  /** The environment's turn about the vertical axis, in degrees. */
  readonly envRotationDeg: number;
  readonly tonemap: (typeof TONE_MAPPINGS)[number];
  readonly exposure: number;
}

/**
 * What a film's colour and its table depend on (src/film/): its media, its stack, its light and its
 * method, and where it is shown in one, the environment (a coloured one is reflected through the
 * film's environment matrix: filmPlanes in filmLight.ts); for a material's film, whether its scene
 * has an environment, which it reflects through that matrix too.
 */
export type FilmOptics = Pick<
  FilmSettings,
  'nOutside' | 'nFilm' | 'nInside' | 'layers' | 'illuminant' | 'lightTint' | 'polarization' | 'normalization' | 'mode'
> &
  Partial<Pick<FilmSettings, 'env'>> & { readonly sceneEnvironment?: boolean };

import { type Medium } from '../physics/medium.ts';
import { FIELDS, type FieldName } from '../fields/fields.ts';
import type { FlowSettings } from '../fields/thicknessField.ts';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type Normalization } from '../physics/spectralWeights.ts';

export const SPACES = ['srgb', 'display-p3', 'wide-gamut'] as const;
/**
 * How the film colour is computed: `exact` the binned spectral integral per fragment (the
 * accuracy reference), `table` one lookup in a GPU-built table, `fourier` the Airy sum as a
 * Fourier series per fragment (a few lookups of the light's spectral transform; nothing to build).
 */
export const MODES = ['exact', 'table', 'fourier'] as const;
/** What a film shader can compute: the modes, and three.js's own iridescence (the benchmark's peer). */
export const FILM_METHODS = [...MODES, 'three-iridescence'] as const;
export { FIELDS };
export const SIDES = ['both', 'front'] as const;
/** Real HDR environments (CC0 equirectangular EXRs, 512 × 256; environmentMaps.ts loads them). */
export const HDR_ENVIRONMENTS = ['park', 'sunset', 'studio', 'city'] as const;
export type HdrEnvironment = (typeof HDR_ENVIRONMENTS)[number];
/** `none` black (the film lit by the light's white: the reference views), `sky` procedural, or a real HDR one. */
export const ENVIRONMENTS = ['sky', 'none', ...HDR_ENVIRONMENTS] as const;
export type Environment = (typeof ENVIRONMENTS)[number];
export const isHdrEnvironment = (env: Environment): env is HdrEnvironment => (HDR_ENVIRONMENTS as readonly string[]).includes(env);
/**
 * How HDR light becomes display values: `none` clips (the reference views stay exact), `agx` and
 * `neutral` are three.js's AgX and Khronos PBR Neutral curves; `auto` is `none` for `none` and
 * `sky`, `agx` for the HDR environments (so the sun and bright windows keep their highlights).
 */
export const TONE_MAPPINGS = ['auto', 'none', 'agx', 'neutral'] as const;
export type ToneMapping = Exclude<(typeof TONE_MAPPINGS)[number], 'auto'>;

/** The tone mapping a view uses (see TONE_MAPPINGS). */
export const toneMappingOf = (s: Pick<FilmSettings, 'tonemap' | 'env'>): ToneMapping =>
  s.tonemap !== 'auto' ? s.tonemap : isHdrEnvironment(s.env) ? 'agx' : 'none';

/** Everything a rendered bubble depends on (the flowing film's FlowSettings included). Ranges and defaults: `filmParameters.ts`. */
export interface FilmSettings extends FlowSettings {
  readonly nOutside: number;
  /** ñ_b: a number, a material, a Cauchy film, a named medium or a complex constant (medium.ts) */
  readonly nFilm: Medium;
  /** ñ_c, the same kinds: an absorbing one (a metal) is opaque */
  readonly nInside: Medium;
  readonly illuminant: IlluminantSpec;
  readonly polarization: Polarization;
  readonly normalization: Normalization;
  readonly space: (typeof SPACES)[number];
  readonly mode: (typeof FILM_METHODS)[number];
  readonly field: FieldName;
  readonly thicknessNm: number;
  readonly thicknessRangeNm: number;
  readonly swirlSpeed: number;
  readonly sides: (typeof SIDES)[number];
  readonly env: Environment;
  /** The environment's turn about the vertical axis, in degrees. */
  readonly envRotationDeg: number;
  readonly tonemap: (typeof TONE_MAPPINGS)[number];
  readonly exposure: number;
  readonly timeSeconds: number;
}

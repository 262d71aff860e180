import { POLARIZATIONS, type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantFromJson } from '../physics/illuminants.ts';
import { NORMALIZATIONS, type Normalization } from '../physics/spectralWeights.ts';
import { type Medium, assertMedium, mediumFromJson, parseMediumText } from '../physics/medium.ts';
import { ParameterError, oneOf } from '../physics/validate.ts';
import { DEFAULT_SETTINGS } from '../settings/filmParameters.ts';
import { type FilmQuality, type FilmQualityOptions, filmQualityFrom } from '../settings/filmQuality.ts';
import { MODES } from '../settings/filmSettings.ts';

/** How the film is computed: `table` (one lookup in a table the GPU builds), `fourier` (the Airy series per fragment) or `exact` (binned integral). */
export type FilmMode = (typeof MODES)[number];

/** A base as given: a medium, or its text (a name is one: `'Ti'`, `'complex:2.6,3.4'`). */
export type BaseInput = Exclude<Medium, string> | string;

/** How the film is computed and seen: the demo's `mode`, `illuminant`, `polarization`, `normalization`, and the quality knobs. */
export interface SpectralIridescenceOptions {
  /** `table` by default */
  readonly mode?: FilmMode;
  readonly illuminant?: IlluminantSpec;
  readonly polarization?: Polarization;
  readonly normalization?: Normalization;
  /**
   * What lies under the film instead of three's `ior`: a medium as the demo's `nInside` takes it
   * (`'Ti'`, `'Au'`, `'complex:2.6,3.4'`, a number, `{ complex: [n, k] }`); null (the default): `ior`.
   * An absorbing base (a metal) is opaque: give the material `color` black and `metalness` 0, so the
   * film over it is all the surface reflects.
   */
  readonly base?: BaseInput | null;
  /** the table's layout and bins: any of the knobs, over the demo's defaults */
  readonly quality?: FilmQualityOptions;
}

/** The options as a spectral material holds them, readable and settable (each set checked as the constructor checks it). */
export interface SpectralIridescenceProperties {
  mode: FilmMode;
  illuminant: IlluminantSpec;
  polarization: Polarization;
  normalization: Normalization;
  base: Medium | null;
  get quality(): FilmQuality;
  /** any of the knobs, over the defaults (not over the current ones) */
  set quality(q: FilmQualityOptions);
}

/** Every option, checked, with its default. */
export type CheckedOptions = Required<Omit<SpectralIridescenceOptions, 'quality' | 'base'>> & {
  readonly quality: FilmQuality;
  readonly base: Medium | null;
};

/** The option names, as the properties of a spectral material are named. */
export const OPTION_NAMES = ['mode', 'illuminant', 'polarization', 'normalization', 'base', 'quality'] as const;

/** The options with their defaults, each checked (a ParameterError names the first bad one). */
export function spectralIridescenceOptions(o: SpectralIridescenceOptions = {}): CheckedOptions {
  return {
    mode: oneOf('mode', o.mode ?? 'table', MODES),
    illuminant: illuminantFromJson(o.illuminant ?? DEFAULT_SETTINGS.illuminant),
    polarization: oneOf('polarization', o.polarization ?? DEFAULT_SETTINGS.polarization, POLARIZATIONS),
    normalization: oneOf('normalization', o.normalization ?? DEFAULT_SETTINGS.normalization, NORMALIZATIONS),
    base: baseOf(o.base ?? null),
    quality: filmQualityFrom(o.quality),
  };
}

/** The base checked as the demo's nInside is (a ParameterError naming `base` when it is not a medium or leaves its domain). */
function baseOf(base: BaseInput | null): Medium | null {
  if (base === null) return null;
  const medium = typeof base === 'string' ? parseMediumText(base) : mediumFromJson(base);
  if (medium === null) throw new ParameterError('base', `base: ${JSON.stringify(base)} is not a medium (a number, a name or complex:n,k)`);
  assertMedium('base', medium, 'inside');
  return medium;
}

/** `options` without the film options' keys, and those keys apart: a one-object constructor's split. */
export function splitFilmOptions<P extends object>(
  parameters: P & SpectralIridescenceOptions,
): [Omit<P, keyof SpectralIridescenceOptions>, SpectralIridescenceOptions] {
  const rest: Record<string, unknown> = { ...(parameters as Record<string, unknown>) };
  const film: Record<string, unknown> = {};
  for (const name of OPTION_NAMES)
    if (name in rest) {
      film[name] = rest[name];
      delete rest[name];
    }
  return [rest as Omit<P, keyof SpectralIridescenceOptions>, film];
}

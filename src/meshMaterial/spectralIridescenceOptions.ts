import { Color } from 'three';
import type { LinearRgb } from '../physics/artistMetal.ts';
import { POLARIZATIONS, type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantFromJson } from '../physics/illuminantSpec.ts';
import { type LightTint, lightTintFromJson } from '../physics/lightTint.ts';
import { NORMALIZATIONS, type Normalization } from '../physics/spectralConventions.ts';
import { type Medium, assertMedium, mediumFromJson, parseMediumText } from '../physics/medium.ts';
import type { FilmLayer } from '../physics/stackFilms.ts';
import { layersText, parseLayers } from '../physics/stackText.ts';
import { ParameterError, isInDomain, oneOf } from '../input/validate.ts';
import { DEFAULT_LIGHT } from '../settings/filmLight.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality, type FilmQualityOptions, filmQualityFrom } from '../settings/filmQuality.ts';
import { MODES } from '../methods/methodRegistry.ts';

/** How the film is computed: `table` (one lookup in a table the GPU builds), `fourier` (the Airy series per fragment) or `exact` (binned integral). */
export type FilmMode = (typeof MODES)[number];

/** A base or a film as given: a medium, or its text (a name is one: `'Ti'`, `'complex:2.6,3.4'`). */
export type BaseInput = Exclude<Medium, string> | string;

/** A stack of films as given: its films, or their text (`'(2.35:56.6/1.46:91.1)*8'`, `'1.68:d/1.43:30'`). */
export type LayersInput = readonly FilmLayer[] | string;

/** An edge tint as given: a three.js Color, a hex number (sRGB, as three reads one) or linear [r, g, b]. */
export type EdgeTintInput = Color | number | LinearRgb;

/** How the film is computed and seen: the demo's `mode`, `illuminant`, `lightTint`, `polarization`, `normalization`, and the quality knobs. */
export interface SpectralIridescenceOptions {
  /** `table` by default */
  readonly mode?: FilmMode;
  readonly illuminant?: IlluminantSpec;
  /** the light's tint, linear sRGB [R, G, B] relative to its white, each in [0, 1]; [1, 1, 1] by default */
  readonly lightTint?: LightTint;
  readonly polarization?: Polarization;
  readonly normalization?: Normalization;
  /**
   * What lies under the film instead of three's `ior`: a medium as the demo's `nInside` takes it
   * (`'Ti'`, `'Au'`, `'complex:2.6,3.4'`, a number, `{ complex: [n, k] }`); null (the default): `ior`.
   * An absorbing base (a metal) is opaque: give the material `color` black and `metalness` 0, so the
   * film over it is all the surface reflects.
   */
  readonly base?: BaseInput | null;
  /**
   * What the film is instead of three's `iridescenceIOR`: a medium as the demo's `nFilm` takes it
   * (`'TiO2'`, `'Fe3O4'`, `'SiO2'`, `'water'`, `'cauchy:1.45,6000'`, a number, `'complex:n,k'`); null
   * (the default): `iridescenceIOR`.
   */
  readonly film?: BaseInput | null;
  /**
   * A metal's edge tint (docs/material.md#a-metal-from-its-colour): with no `base` and `metalness`
   * > 0, the film lies on a metal whose complex index comes from the base `color` (its F0) and this
   * colour (Gulbrandsen 2014). A three.js `Color`, a hex number (sRGB) or linear `[r, g, b]` in
   * [0, 1]; null (the default): the base colour itself.
   */
  readonly edgeTint?: EdgeTintInput | null;
  /**
   * A stack of films in place of the one film (docs/physics.md#stacks-of-films): its films from the
   * outside in, as the demo's `layers` takes them (`'(2.35:56.6/1.46:91.1)*8'`, or
   * `[{ n: 1.68, thicknessNm: 'd' }, …]`), over the base. A `d` layer takes the glTF iridescence
   * thickness (iridescenceThicknessRange, iridescenceThicknessMap); empty (the default): the film.
   */
  readonly layers?: LayersInput;
  /** the table's layout and bins: any of the knobs, over the demo's defaults */
  readonly quality?: FilmQualityOptions;
}

/**
 * The options as a spectral material holds them (OPTION_NAMES), readable and settable: each read
 * gives the option checked, each set takes it as `spectralIridescence` does (and checks it so).
 */
export interface SpectralIridescenceProperties {
  mode: FilmMode;
  illuminant: IlluminantSpec;
  lightTint: LightTint;
  polarization: Polarization;
  normalization: Normalization;
  get base(): Medium | null;
  /** a medium or its text (`'Ti'`, `'complex:2.6,3.4'`), or null for three's `ior` */
  set base(value: BaseInput | null);
  get film(): Medium | null;
  /** a medium or its text (`'TiO2'`, `'Fe3O4'`), or null for three's `iridescenceIOR` */
  set film(value: BaseInput | null);
  get edgeTint(): LinearRgb | null;
  /** a metal's edge tint (a Color, a hex number, linear [r, g, b]), or null for the base colour */
  set edgeTint(value: EdgeTintInput | null);
  get layers(): readonly FilmLayer[];
  /** the films or their text; empty for the one film */
  set layers(value: LayersInput);
  get quality(): FilmQuality;
  /** any of the knobs, over the defaults (not over the current ones) */
  set quality(value: FilmQualityOptions);
}

/** Every option, checked, with its default. */
export type CheckedOptions = Required<Omit<SpectralIridescenceOptions, 'quality' | 'base' | 'film' | 'edgeTint' | 'layers'>> & {
  readonly quality: FilmQuality;
  readonly layers: readonly FilmLayer[];
  readonly base: Medium | null;
  readonly film: Medium | null;
  readonly edgeTint: LinearRgb | null;
};

/** The option names, as the properties of a spectral material are named. */
export const OPTION_NAMES = [
  'mode',
  'illuminant',
  'lightTint',
  'polarization',
  'normalization',
  'base',
  'film',
  'edgeTint',
  'layers',
  'quality',
] as const satisfies readonly (keyof SpectralIridescenceProperties)[];

/**
 * The material's default quality: the bubble's, with a table of 6 nm cells at its thick end
 * instead of 8. three's lobe (its DFG term, the F0 the film is solved into) adds an error of its
 * own to the table's, and finer cells along thickness keep the whole material's pixels within the
 * bound tests/e2e/materialGrid.spec.ts holds (docs/material.md#the-films-f0-for-image-based-light;
 * the figures: docs/benchmarks.md). The table is wider for it, built once per film.
 */
export const MATERIAL_FILM_QUALITY: FilmQuality = { ...DEFAULT_FILM_QUALITY, table: { ...DEFAULT_FILM_QUALITY.table, thickEndCellNm: 6 } };

/** The options with their defaults, each checked (a ParameterError names the first bad one). */
export function spectralIridescenceOptions(o: SpectralIridescenceOptions = {}): CheckedOptions {
  return {
    mode: oneOf('mode', o.mode ?? 'table', MODES),
    illuminant: illuminantFromJson(o.illuminant ?? DEFAULT_LIGHT.illuminant),
    lightTint: lightTintFromJson(o.lightTint ?? DEFAULT_LIGHT.lightTint),
    polarization: oneOf('polarization', o.polarization ?? DEFAULT_LIGHT.polarization, POLARIZATIONS),
    normalization: oneOf('normalization', o.normalization ?? DEFAULT_LIGHT.normalization, NORMALIZATIONS),
    base: mediumOf('base', o.base ?? null, 'inside'),
    film: mediumOf('film', o.film ?? null, 'film'),
    edgeTint: edgeTintOf(o.edgeTint ?? null),
    layers: layersOf(o.layers ?? []),
    quality: filmQualityFrom(o.quality, MATERIAL_FILM_QUALITY),
  };
}

/** The base or the film checked as the demo's nInside or nFilm is (a ParameterError naming it when it is not a medium or leaves its domain). */
function mediumOf(name: 'base' | 'film', given: BaseInput | null, role: 'inside' | 'film'): Medium | null {
  if (given === null) return null;
  const medium = typeof given === 'string' ? parseMediumText(given) : mediumFromJson(given);
  if (medium === null)
    throw new ParameterError(name, `${name}: ${JSON.stringify(given)} is not a medium (a number, a name or complex:n,k)`);
  assertMedium(name, medium, role);
  return medium;
}

/**
 * The films checked as the demo's `layers` is (parseLayers: each film's medium and thickness, the
 * count): a text read, a list written as its text and read back (a ParameterError naming `layers`).
 */
function layersOf(given: LayersInput): readonly FilmLayer[] {
  if (given === '' || (Array.isArray(given) && given.length === 0)) return [];
  if (typeof given === 'string') return parseLayers('layers', given);
  const isLayer = (l: unknown) => typeof l === 'object' && l !== null && 'n' in l && 'thicknessNm' in l;
  if (!Array.isArray(given) || !given.every(isLayer))
    throw new ParameterError(
      'layers',
      `layers: ${JSON.stringify(given)} is not allowed; expected a list of { n, thicknessNm } or its text`,
    );
  return parseLayers('layers', layersText(given as readonly FilmLayer[]));
}

const UNIT = { min: 0, max: 1, unit: '' } as const;

/** The edge tint as linear [r, g, b] (a ParameterError naming `edgeTint` when a component leaves [0, 1] or it is no colour). */
function edgeTintOf(tint: EdgeTintInput | null): LinearRgb | null {
  if (tint === null) return null;
  const isHex = typeof tint === 'number' && Number.isInteger(tint) && tint >= 0 && tint <= 0xffffff;
  const rgb: unknown[] = tint instanceof Color ? tint.toArray() : isHex ? new Color(tint).toArray() : Array.isArray(tint) ? [...tint] : [];
  if (rgb.length !== 3 || !rgb.every((c) => typeof c === 'number' && isInDomain(c, UNIT)))
    throw new ParameterError(
      'edgeTint',
      `edgeTint: ${JSON.stringify(tint)} is not allowed; expected a Color, a hex number or linear [r, g, b] each in [0, 1]`,
    );
  return rgb as unknown as LinearRgb;
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

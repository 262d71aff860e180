import { FILM_STACK_DOMAIN, type FilmStack, type Polarization, POLARIZATIONS, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantFromJson } from '../physics/illuminants.ts';
import { type LightTint, lightTintFromJson } from '../physics/lightTint.ts';
import {
  type Medium,
  type MediumRole,
  mediumExpected,
  mediumFromJson,
  mediumProblem,
  mediumRangeNm,
  mediumText,
} from '../physics/medium.ts';
import { type Normalization, NORMALIZATIONS } from '../physics/spectralWeights.ts';
import { FIELD_THICKNESS, type FilmLayer, LAYERS_DOMAIN, followsField } from '../physics/stackFilms.ts';
import { isInDomain, type NumberDomain, oneOf, ParameterError, rejectValue, expectedNumber } from '../input/validate.ts';
import { DEFAULT_SETTINGS, FILM_PARAMETERS } from '../settings/filmParameters.ts';

/** One film to colour: what the command line or one entry of a cases file describes. */
export interface ColorCase {
  readonly id: string | number;
  /** The single film; with `films`, its nOutside, nInside and angle, and its thickness that of every FIELD_THICKNESS film. */
  readonly stack: FilmStack<Medium>;
  /** The films its option `layers` stacks in place of the stack's single film (stackFilms.ts); empty: the single film. */
  readonly films: readonly FilmLayer[];
  readonly illuminant: IlluminantSpec;
  readonly lightTint: LightTint;
  readonly polarization: Polarization;
  readonly normalization: Normalization;
  /** Wavelengths at which R(λ) is reported as well. */
  readonly wavelengthsNm: readonly number[];
}

/**
 * The numeric fields of a case, with their domain (FILM_STACK_DOMAIN, filmReflectance.ts) and
 * the default when a case leaves one out: a 500 nm soap film in air seen head-on.
 */
export const NUMBER_FIELDS = {
  thicknessNm: { ...FILM_STACK_DOMAIN.thicknessNm, fallback: 500 },
  angleDeg: { ...FILM_STACK_DOMAIN.angleDeg, fallback: 0 },
} as const satisfies Record<string, NumberDomain & { fallback: number }>;
export type NumberField = keyof typeof NUMBER_FIELDS;

/** The media of a case (medium.ts), each with its role and default: soap film in air. */
export const MEDIUM_FIELDS = {
  nOutside: { role: 'outside', fallback: SOAP_FILM_IN_AIR.nOutside },
  nInside: { role: 'inside', fallback: SOAP_FILM_IN_AIR.nInside },
  nFilm: { role: 'film', fallback: SOAP_FILM_IN_AIR.nFilm },
} as const satisfies Record<string, { role: MediumRole; fallback: Medium }>;
export type MediumField = keyof typeof MEDIUM_FIELDS;

export const CASE_FIELDS = [
  'id',
  ...(Object.keys(NUMBER_FIELDS) as NumberField[]),
  ...(Object.keys(MEDIUM_FIELDS) as MediumField[]),
  'layers',
  'illuminant',
  'lightTint',
  'polarization',
  'normalization',
  'wavelengthsNm',
] as const;
export type CaseField = (typeof CASE_FIELDS)[number];

/** Where R(λ) may be asked for: the range of the CIE daylight tables. */
export const WAVELENGTH_DOMAIN_NM: NumberDomain = { min: 300, max: 830, unit: 'nm' };
export const MAX_WAVELENGTHS = 10_000;
export const MAX_ID_CHARS = 200;
/** A flag that sets one field of a case (or of every row of a table), as the usage shows it. */
export interface CaseFlag {
  readonly flag: string;
  readonly field: Exclude<CaseField, 'id'>;
  readonly label: string;
  readonly expected: string;
  /** The default, as the usage shows it ('' for none). */
  readonly defaultText: string;
}

/** The case fields the view's parameter schema also has: their flag, label and domain come from its rows. */
const SHARED_FLAGS: readonly CaseFlag[] = FILM_PARAMETERS.filter((row) => (CASE_FIELDS as readonly string[]).includes(row.key)).map(
  (row) => ({
    flag: row.flag,
    field: row.key as CaseFlag['field'],
    label: row.label,
    // The colour tool takes absorbing media too (the view's schema does not yet).
    expected: row.key in MEDIUM_FIELDS ? mediumExpected(MEDIUM_FIELDS[row.key as MediumField].role) : row.expected,
    defaultText: row.key in NUMBER_FIELDS ? String(NUMBER_FIELDS[row.key as NumberField].fallback) : row.defaultText,
  }),
);

/** The colour tool's case flags: the shared ones, then its own. */
export const CASE_FLAGS: readonly CaseFlag[] = [
  ...SHARED_FLAGS,
  {
    flag: 'angle',
    field: 'angleDeg',
    label: 'angle of incidence (degrees)',
    expected: expectedNumber(NUMBER_FIELDS.angleDeg),
    defaultText: '0',
  },
  {
    flag: 'wavelengths',
    field: 'wavelengthsNm',
    label: 'also report R(λ) at these wavelengths',
    expected: `comma-separated, each ${expectedNumber(WAVELENGTH_DOMAIN_NM)}`,
    defaultText: '',
  },
];

/** A case's fields before checking: numbers already numbers, absent fields undefined. */
export type RawCase = Readonly<Partial<Record<CaseField, unknown>>>;

/**
 * The checked case, defaults filled in, or a ParameterError for the first bad field.
 * `nameOf` says how a field is called where it came from (`--thickness` on the command line).
 */
export function validateColorCase(
  raw: RawCase,
  index: number,
  nameOf: (field: CaseField) => string = (f) => f,
  layerThickness: LayerThickness = 'own',
): ColorCase {
  const number = (field: NumberField): number => {
    const d = NUMBER_FIELDS[field];
    const value = raw[field];
    if (value === undefined) return d.fallback;
    return isInDomain(value, d) ? value : rejectValue(nameOf(field), value, expectedNumber(d));
  };
  const orDefault = (field: CaseField, fallback: string) => (raw[field] === undefined ? fallback : raw[field]);
  const films = raw.layers === undefined ? [] : validateLayers(raw, nameOf, layerThickness);
  const stack: FilmStack<Medium> = {
    nOutside: validateMedium(raw.nOutside, 'nOutside', nameOf('nOutside')),
    nFilm: validateMedium(raw.nFilm, 'nFilm', nameOf('nFilm')),
    nInside: validateMedium(raw.nInside, 'nInside', nameOf('nInside')),
    thicknessNm: number('thicknessNm'),
    angleDeg: number('angleDeg'),
  };
  return {
    id: validateId(raw.id, index, nameOf('id')),
    stack,
    films,
    illuminant: raw.illuminant === undefined ? DEFAULT_SETTINGS.illuminant : illuminantFromJson(raw.illuminant, nameOf('illuminant')),
    lightTint: raw.lightTint === undefined ? DEFAULT_SETTINGS.lightTint : lightTintFromJson(raw.lightTint, nameOf('lightTint')),
    polarization: oneOf(nameOf('polarization'), orDefault('polarization', DEFAULT_SETTINGS.polarization), POLARIZATIONS),
    normalization: oneOf(nameOf('normalization'), orDefault('normalization', DEFAULT_SETTINGS.normalization), NORMALIZATIONS),
    wavelengthsNm: validateWavelengths(raw.wavelengthsNm, nameOf('wavelengthsNm'), stack, films),
  };
}

/** An id is a string (≤ MAX_ID_CHARS) or a finite number; absent, it is the case's index. */
export const isValidId = (id: unknown): id is string | number =>
  (typeof id === 'string' && id.length <= MAX_ID_CHARS) || (typeof id === 'number' && Number.isFinite(id));

function validateId(id: unknown, index: number, name: string): string | number {
  if (id === undefined) return index;
  return isValidId(id) ? id : rejectValue(name, id, `a string of at most ${MAX_ID_CHARS} characters or a number`);
}

/**
 * A medium (medium.ts): a number, a material's name, { cauchy: [A, B(, C)] } or { complex: [n, k] },
 * allowed in its role (the outside: a real constant in its domain). The outside comes back a number.
 */
function validateMedium(value: unknown, field: MediumField, name: string): Medium {
  const { role, fallback } = MEDIUM_FIELDS[field];
  return value === undefined ? fallback : validateMediumIn(value, role, name);
}

/** A medium given as JSON, allowed in its role. */
function validateMediumIn(value: unknown, role: MediumRole, name: string): Medium {
  const medium = mediumFromJson(value);
  if (medium === null) return rejectValue(name, value, mediumExpected(role));
  const problem = mediumProblem(medium, role);
  return problem === null ? medium : rejectValue(name, value, `${mediumExpected(role)} (here ${problem})`);
}

/**
 * Where a case's films take their thickness from: `own`, each its number (a cases file, where
 * `thicknessNm` is the single film's); `orField`, a number or FIELD_THICKNESS, the case's
 * thicknessNm (the command line's --layers, whose --thickness and thickness tables set it).
 */
export type LayerThickness = 'own' | 'orField';

/** What a cases file's `layers` is. */
const LAYERS_JSON_EXPECTED = `an array of ${LAYERS_DOMAIN.count.min} to ${LAYERS_DOMAIN.count.max} objects { "n": a medium as nFilm takes it, "thicknessNm": ${expectedNumber(LAYERS_DOMAIN.thicknessNm)} }, outside in`;

/**
 * A case's stack of films: `[{ "n", "thicknessNm" }, …]` (the command line's --layers arrives
 * parsed into the same form), each n a medium a film takes. A case with `layers` gives no nFilm (each
 * layer has its own), and in a cases file no thicknessNm (each layer has its own, and none takes
 * the case's: FIELD_THICKNESS is refused there).
 */
function validateLayers(raw: RawCase, nameOf: (field: CaseField) => string, layerThickness: LayerThickness): readonly FilmLayer[] {
  const name = nameOf('layers');
  const clash = (field: CaseField, why: string): never => {
    throw new ParameterError(name, `${name}: not allowed with ${nameOf(field)} (${why})`);
  };
  if (raw.nFilm !== undefined) clash('nFilm', 'each layer has its own index');
  if (raw.thicknessNm !== undefined && layerThickness === 'own') clash('thicknessNm', 'each layer has its own thicknessNm');
  const value = raw.layers;
  const { count, thicknessNm: thickness } = LAYERS_DOMAIN;
  if (!Array.isArray(value) || value.length < count.min || value.length > count.max) return rejectValue(name, value, LAYERS_JSON_EXPECTED);
  const films = value.map((entry: unknown, i): FilmLayer => {
    const isLayer = typeof entry === 'object' && entry !== null && !Array.isArray(entry);
    if (!isLayer || Object.keys(entry).sort().join() !== 'n,thicknessNm') return rejectValue(`${name}[${i}]`, entry, LAYERS_JSON_EXPECTED);
    const { n, thicknessNm } = entry as { n: unknown; thicknessNm: unknown };
    const medium = validateMediumIn(n, 'film', `${name}[${i}].n`);
    if (thicknessNm === FIELD_THICKNESS && layerThickness === 'orField') return { n: medium, thicknessNm };
    if (thicknessNm === FIELD_THICKNESS) {
      const why = `"${FIELD_THICKNESS}", the thickness field's value, is for the view and --layers: a case's layers have their own thicknesses`;
      return rejectValue(`${name}[${i}].thicknessNm`, thicknessNm, `${expectedNumber(thickness)} (${why})`);
    }
    return isInDomain(thicknessNm, thickness)
      ? { n: medium, thicknessNm }
      : rejectValue(`${name}[${i}].thicknessNm`, thicknessNm, expectedNumber(thickness));
  });
  if (raw.thicknessNm !== undefined && !followsField(films)) {
    const message = `${nameOf('thicknessNm')}: not allowed with ${name} that has no ${FIELD_THICKNESS} layer (no layer takes the thickness)`;
    throw new ParameterError(nameOf('thicknessNm'), message);
  }
  return films;
}

/**
 * Wavelengths within WAVELENGTH_DOMAIN_NM and within the range of every medium's source (a metal's
 * table ends near 368 nm, so R(300 nm) on gold has no data behind it).
 */
function validateWavelengths(value: unknown, name: string, stack: FilmStack<Medium>, films: readonly FilmLayer[]): readonly number[] {
  if (value === undefined) return [];
  let domain = WAVELENGTH_DOMAIN_NM;
  let why = '';
  const media: [string, Medium][] = films.length === 0 ? [['nFilm', stack.nFilm]] : films.map((l, i) => [`layers[${i}].n`, l.n]);
  for (const [field, medium] of [...media, ['nInside', stack.nInside] as [string, Medium]]) {
    const range = mediumRangeNm(medium);
    if (range && (range.min > domain.min || range.max < domain.max)) {
      domain = { ...domain, min: Math.max(domain.min, range.min), max: Math.min(domain.max, range.max) };
      why = ` (where ${field} ${mediumText(medium)} has data)`;
    }
  }
  const expected = `${expectedNumber(domain)}${why}`;
  if (!Array.isArray(value)) return rejectValue(name, value, `an array of numbers, each ${expected}`);
  if (value.length > MAX_WAVELENGTHS) return rejectValue(name, value, `at most ${MAX_WAVELENGTHS} wavelengths`);
  value.forEach((v: unknown, i) => isInDomain(v, domain) || rejectValue(`${name}[${i}]`, v, expected));
  return value as number[];
}

import { FILM_STACK_DOMAIN, type Polarization, POLARIZATIONS, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantFromJson } from '../physics/illuminants.ts';
import {
  type Medium,
  type MediumRole,
  type MediumStack,
  mediumExpected,
  mediumFromJson,
  mediumProblem,
  mediumRangeNm,
  mediumText,
} from '../physics/medium.ts';
import { type Normalization, NORMALIZATIONS } from '../physics/spectralWeights.ts';
import { isInDomain, type NumberDomain, oneOf, rejectValue, expectedNumber } from '../input/validate.ts';
import { DEFAULT_SETTINGS, FILM_PARAMETERS } from '../settings/filmParameters.ts';

/** One film to colour: what the command line or one entry of a cases file describes. */
export interface ColorCase {
  readonly id: string | number;
  readonly stack: MediumStack;
  readonly illuminant: IlluminantSpec;
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
  'illuminant',
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
const SHARED_FLAGS: readonly CaseFlag[] = FILM_PARAMETERS.flatMap((row) =>
  row.cli === null
    ? []
    : [
        {
          flag: row.cli,
          field: row.key as CaseFlag['field'],
          label: row.label,
          // The colour tool takes absorbing media too (the view's schema does not yet).
          expected: row.key in MEDIUM_FIELDS ? mediumExpected(MEDIUM_FIELDS[row.key as MediumField].role) : row.expected,
          defaultText: row.key in NUMBER_FIELDS ? String(NUMBER_FIELDS[row.key as NumberField].fallback) : row.defaultText,
        },
      ],
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
export function validateColorCase(raw: RawCase, index: number, nameOf: (field: CaseField) => string = (f) => f): ColorCase {
  const number = (field: NumberField): number => {
    const d = NUMBER_FIELDS[field];
    const value = raw[field];
    if (value === undefined) return d.fallback;
    return isInDomain(value, d) ? value : rejectValue(nameOf(field), value, expectedNumber(d));
  };
  const orDefault = (field: CaseField, fallback: string) => (raw[field] === undefined ? fallback : raw[field]);
  const stack: MediumStack = {
    nOutside: validateMedium(raw.nOutside, 'nOutside', nameOf('nOutside')) as number,
    nFilm: validateMedium(raw.nFilm, 'nFilm', nameOf('nFilm')),
    nInside: validateMedium(raw.nInside, 'nInside', nameOf('nInside')),
    thicknessNm: number('thicknessNm'),
    angleDeg: number('angleDeg'),
  };
  return {
    id: validateId(raw.id, index, nameOf('id')),
    stack,
    illuminant: raw.illuminant === undefined ? DEFAULT_SETTINGS.illuminant : illuminantFromJson(raw.illuminant, nameOf('illuminant')),
    polarization: oneOf(nameOf('polarization'), orDefault('polarization', DEFAULT_SETTINGS.polarization), POLARIZATIONS),
    normalization: oneOf(nameOf('normalization'), orDefault('normalization', DEFAULT_SETTINGS.normalization), NORMALIZATIONS),
    wavelengthsNm: validateWavelengths(raw.wavelengthsNm, nameOf('wavelengthsNm'), stack),
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
  if (value === undefined) return fallback;
  const medium = mediumFromJson(value);
  if (medium === null) return rejectValue(name, value, mediumExpected(role));
  const problem = mediumProblem(medium, role);
  return problem === null ? medium : rejectValue(name, value, `${mediumExpected(role)} (here ${problem})`);
}

/**
 * Wavelengths within WAVELENGTH_DOMAIN_NM and within the range of every medium's source (a metal's
 * table ends near 368 nm, so R(300 nm) on gold has no data behind it).
 */
function validateWavelengths(value: unknown, name: string, stack: MediumStack): readonly number[] {
  if (value === undefined) return [];
  let domain = WAVELENGTH_DOMAIN_NM;
  let why = '';
  for (const field of ['nFilm', 'nInside'] as const) {
    const range = mediumRangeNm(stack[field]);
    if (range && (range.min > domain.min || range.max < domain.max)) {
      domain = { ...domain, min: Math.max(domain.min, range.min), max: Math.min(domain.max, range.max) };
      why = ` (where ${field} ${mediumText(stack[field])} has data)`;
    }
  }
  const expected = `${expectedNumber(domain)}${why}`;
  if (!Array.isArray(value)) return rejectValue(name, value, `an array of numbers, each ${expected}`);
  if (value.length > MAX_WAVELENGTHS) return rejectValue(name, value, `at most ${MAX_WAVELENGTHS} wavelengths`);
  value.forEach((v: unknown, i) => isInDomain(v, domain) || rejectValue(`${name}[${i}]`, v, expected));
  return value as number[];
}

import { type RefractiveIndex, asComplex, realIndex } from './complex.ts';
import {
  DISPERSION_CHECK_NM,
  FILM_INDEX_EXPECTED,
  type FilmIndex,
  filmIndexAt,
  filmIndexFromJson,
  filmIndexProblem,
  filmIndexText,
  isDispersive,
  parseFilmIndexText,
} from './filmIndex.ts';
import { COMPLEX_INDEX_DOMAIN, type FilmStack, FILM_STACK_DOMAIN, complexIndexProblem } from './filmReflectance.ts';
import { type MediumName, NAMED_MEDIA, type NamedMedium, isMediumName, namedIndex, namedRangeNm } from './namedMedia.ts';
import { type SampledIndex, isSampledIndex, sampledIndexAt } from './sampledIndex.ts';
import { ParameterError, expectedNumber, parseDecimal } from '../input/validate.ts';

/**
 * What a film or the inside is made of (docs/physics.md#absorbing-media):
 * - a FilmIndex (filmIndex.ts): a real number, `water` or a Cauchy film;
 * - a named medium (namedMedia.ts): water, a metal or an oxide from a published table or formula;
 * - a constant complex index ñ = n + ik, `complex:n,k` ({ complex: [n, k] } in JSON), k ≥ 0;
 * - a SampledIndex (sampledIndex.ts): ñ at a few wavelengths, made in code (a metal from its
 *   colour, artistMetal.ts), never read from a text.
 * The outside, where the light comes from, is always a real constant.
 */
export interface ComplexConstant {
  /** [n, k]: ñ = n + ik */
  readonly complex: readonly [number, number];
}
export type Medium = FilmIndex | NamedMedium | ComplexConstant | SampledIndex;

/** Which layer a medium is for: the outside takes a real constant only. */
export type MediumRole = 'outside' | 'film' | 'inside';

/** Where a medium's source gives values (null: at every λ). */
type RangeNm = { readonly min: number; readonly max: number } | null;

/**
 * What the functions below ask of one kind of medium; each kind answers for its own. `problem` is
 * for the film and the inside (the outside takes a number only, mediumProblem); `parse` and
 * `fromJson` give null for what is not of the kind; `expected`, where set, is what a refusal of
 * the kind states in place of mediumExpected.
 */
interface MediumKind<M extends Medium> {
  readonly is: (m: Medium) => m is M;
  readonly indexAt: (m: M, lambdaNm: number) => RefractiveIndex;
  readonly dispersive: (m: M) => boolean;
  readonly absorbsInBand: (m: M) => boolean;
  readonly rangeNm: (m: M) => RangeNm;
  readonly text: (m: M) => string;
  readonly problem: (m: M) => string | null;
  readonly parse: (text: string) => M | null;
  readonly fromJson: (value: unknown) => M | null;
  readonly expected?: string;
}

/** Where `absorbsInBand` looks at k: every 5 nm of the colour band. */
const ABSORPTION_CHECK_STEP_NM = 5;

/** Whether ñ(λ) has k > 0 anywhere in the colour band (DISPERSION_CHECK_NM, every 5 nm). */
function absorbsSomewhereInBand(indexAt: (lambdaNm: number) => RefractiveIndex): boolean {
  for (let l = DISPERSION_CHECK_NM.min; l <= DISPERSION_CHECK_NM.max; l += ABSORPTION_CHECK_STEP_NM) {
    const v = indexAt(l);
    if (typeof v !== 'number' && v.im > 0) return true;
  }
  return false;
}

/** Each named medium's answer to absorbsInBand, found the first time it is asked. */
const namedAbsorbs = new Map<MediumName, boolean>();

/** A name from the registry (namedMedia.ts): its data is read only for its index and whether it absorbs. */
const NAMED: MediumKind<MediumName> = {
  is: (m): m is MediumName => isMediumName(m),
  indexAt: (m, lambdaNm) => namedIndex(m)(lambdaNm),
  dispersive: () => true,
  absorbsInBand: (m) => {
    let absorbs = namedAbsorbs.get(m);
    if (absorbs === undefined) namedAbsorbs.set(m, (absorbs = absorbsSomewhereInBand(namedIndex(m))));
    return absorbs;
  },
  rangeNm: namedRangeNm,
  text: (m) => m,
  // A named medium's source keeps n and k inside COMPLEX_INDEX_DOMAIN over its range (a unit test holds every one).
  problem: () => null,
  parse: (text) => (isMediumName(text) ? text : null),
  fromJson: (value) => (isMediumName(value) ? value : null),
};

const COMPLEX: MediumKind<ComplexConstant> = {
  is: (m): m is ComplexConstant => typeof m === 'object' && 'complex' in m,
  indexAt: (m) => ({ re: m.complex[0], im: m.complex[1] }),
  dispersive: () => false,
  absorbsInBand: (m) => m.complex[1] > 0,
  rangeNm: () => null,
  text: (m) => `complex:${m.complex[0]},${m.complex[1]}`,
  problem: ({ complex: [n, k] }) => complexIndexProblem({ re: n, im: k }),
  parse: (text) => {
    if (!text.startsWith('complex:')) return null;
    const parts = text.slice('complex:'.length).split(',').map(parseDecimal);
    return parts.length === 2 && parts.every(Number.isFinite) ? { complex: [parts[0]!, parts[1]!] } : null;
  },
  fromJson: (value) => {
    const isObject = typeof value === 'object' && value !== null && !Array.isArray(value);
    if (!isObject || Object.keys(value).join() !== 'complex') return null;
    const nk = (value as { complex: unknown }).complex;
    const isPair = Array.isArray(nk) && nk.length === 2 && nk.every((t) => typeof t === 'number');
    return isPair ? { complex: [nk[0] as number, nk[1] as number] } : null;
  },
};

/** Made in code only (artistMetal.ts), never read from a text or a file. */
const SAMPLED: MediumKind<SampledIndex> = {
  is: isSampledIndex,
  indexAt: sampledIndexAt,
  dispersive: () => true,
  absorbsInBand: (m) => m.sampled.some(([, , k]) => k > 0),
  rangeNm: () => null,
  text: (m) => `sampled:${m.sampled.map(([l, n, k]) => `${l}:${n},${k}`).join(';')}`,
  problem: (m) => m.sampled.map(([, n, k]) => complexIndexProblem({ re: n, im: k })).find((p) => p !== null) ?? null,
  parse: () => null,
  fromJson: () => null,
};

/** A number or a Cauchy film (filmIndex.ts; a named material is NAMED's): real, so never absorbing. */
const FILM_INDEX: MediumKind<FilmIndex> = {
  is: (m): m is FilmIndex => typeof m === 'number' || (typeof m === 'object' && 'cauchy' in m),
  indexAt: filmIndexAt,
  dispersive: isDispersive,
  absorbsInBand: () => false,
  rangeNm: () => null,
  text: filmIndexText,
  problem: filmIndexProblem,
  parse: parseFilmIndexText,
  fromJson: filmIndexFromJson,
  expected: FILM_INDEX_EXPECTED,
};

/** Every kind, in the order a text or a JSON value is tried against them. */
const KINDS = [NAMED, COMPLEX, SAMPLED, FILM_INDEX] as readonly MediumKind<Medium>[];

/** The kind of a medium. */
const kindOf = (m: Medium): MediumKind<Medium> => KINDS.find((kind) => kind.is(m))!;

/** ñ at λ in nm: a number for a FilmIndex (exactly filmIndexAt), ñ = n + ik otherwise (k may be 0). */
export const mediumIndexAt = (m: Medium, lambdaNm: number): RefractiveIndex => kindOf(m).indexAt(m, lambdaNm);

/** n at λ of a medium used where light arrives from it (transparent there: its k is 0). */
export const transparentIndexAt = (m: Medium, lambdaNm: number): number => asComplex(mediumIndexAt(m, lambdaNm)).re;

/** Whether ñ depends on λ. */
export const isDispersiveMedium = (m: Medium): boolean => kindOf(m).dispersive(m);

/**
 * Whether the medium absorbs (k > 0) anywhere in the colour band (DISPERSION_CHECK_NM, every 5 nm):
 * as an inside it is then opaque, T = 0 (docs/physics.md#absorbing-media).
 */
export const absorbsInBand = (m: Medium): boolean => kindOf(m).absorbsInBand(m);

/** Where the medium's source gives values (null: at every λ). */
export const mediumRangeNm = (m: Medium): RangeNm => kindOf(m).rangeNm(m);

/** The film at one wavelength. */
export const mediumStackAt = (stack: FilmStack<Medium>, lambdaNm: number): FilmStack<RefractiveIndex> => ({
  ...stack,
  nOutside: transparentIndexAt(stack.nOutside, lambdaNm),
  nFilm: mediumIndexAt(stack.nFilm, lambdaNm),
  nInside: mediumIndexAt(stack.nInside, lambdaNm),
});

/** The medium as URL, attribute and command line write it: `1.33`, `water`, `cauchy:1.45,6000`, `Au`, `complex:0.43,2.455`. */
export const mediumText = (m: Medium): string => kindOf(m).text(m);

/** What a role accepts, as every refusal states it. */
export function mediumExpected(role: MediumRole): string {
  if (role === 'outside') return expectedNumber(FILM_STACK_DOMAIN.nOutside);
  const { n, k } = COMPLEX_INDEX_DOMAIN;
  return `${FILM_INDEX_EXPECTED}; ${NAMED_MEDIA.join(', ')}; or complex:n,k (ñ = n + ik, n in [${n.min}, ${n.max}], k in [${k.min}, ${k.max}])`;
}

/** The first of the kinds' readings that is not null. */
const firstReading = (read: (kind: MediumKind<Medium>) => Medium | null): Medium | null => {
  for (const kind of KINDS) {
    const m = read(kind);
    if (m !== null) return m;
  }
  return null;
};

/** The medium a text writes (`complex:n,k`, a name, or what parseFilmIndexText reads), whatever its range, or null. */
export const parseMediumText = (text: string): Medium | null => firstReading((kind) => kind.parse(text));

/** A cases file's value: what filmIndexFromJson reads, a named medium, or `{ "complex": [n, k] }`; null when none. */
export const mediumFromJson = (value: unknown): Medium | null => firstReading((kind) => kind.fromJson(value));

/** What is wrong with a medium in a role (null: nothing), in words a message can quote. */
export function mediumProblem(m: Medium, role: MediumRole): string | null {
  if (role !== 'outside') return kindOf(m).problem(m);
  const { min, max } = FILM_STACK_DOMAIN.nOutside;
  if (typeof m !== 'number') return 'the outside is transparent: a constant real index';
  return m >= min && m <= max ? null : `n is ${m}, outside [${min}, ${max}]`;
}

/** Throws a ParameterError naming `name` when the medium is not allowed in its role. */
export function assertMedium(name: string, m: Medium, role: MediumRole): void {
  const problem = mediumProblem(m, role);
  if (!problem) return;
  const expected = (role !== 'outside' && kindOf(m).expected) || mediumExpected(role);
  throw new ParameterError(name, `${name}: ${mediumText(m)} is not allowed (${problem}); expected ${expected}`);
}

/** The checked medium of a text for a role, or why it is refused (null: the text is no medium at all; `mediumExpected` says what is). */
export function readMedium(text: string, role: MediumRole): { readonly medium: Medium } | { readonly problem: string | null } {
  const medium = parseMediumText(text);
  if (medium === null) return { problem: null };
  const problem = mediumProblem(medium, role);
  return problem ? { problem } : { medium };
}

/** An index as JSON reports it: a number when real (k = 0), { n, k } when it absorbs. */
export type IndexJson = number | { readonly n: number; readonly k: number };
export function indexJson(index: RefractiveIndex): IndexJson {
  const real = realIndex(index);
  return real ?? { n: (index as { re: number }).re, k: (index as { im: number }).im };
}

import { type RefractiveIndex, asComplex, realIndex } from './complex.ts';
import {
  DISPERSION_CHECK_NM,
  FILM_INDEX_EXPECTED,
  type FilmIndex,
  assertFilmIndex,
  filmIndexAt,
  filmIndexFromJson,
  filmIndexProblem,
  filmIndexText,
  isDispersive,
  parseFilmIndexText,
} from './filmIndex.ts';
import { COMPLEX_INDEX_DOMAIN, type FilmStack, FILM_STACK_DOMAIN, complexIndexProblem } from './filmReflectance.ts';
import { NAMED_MEDIA, NAMED_MEDIUM_INDEX, type NamedMedium, isNamedMedium } from './namedMedia.ts';
import { type SampledIndex, isSampledIndex, sampledIndexAt } from './sampledIndex.ts';
import { ParameterError, expectedNumber, parseDecimal } from '../input/validate.ts';

/**
 * What a film or the inside is made of (docs/physics.md#absorbing-media):
 * - a FilmIndex (filmIndex.ts): a real number, `water` or a Cauchy film;
 * - a named medium (namedMedia.ts): a metal or an oxide from a published table or formula;
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

const isComplexConstant = (m: Medium): m is ComplexConstant => typeof m === 'object' && 'complex' in m;

/** ñ at λ in nm: a number for a FilmIndex (exactly filmIndexAt), ñ = n + ik otherwise (k may be 0). */
export function mediumIndexAt(m: Medium, lambdaNm: number): RefractiveIndex {
  if (isComplexConstant(m)) return { re: m.complex[0], im: m.complex[1] };
  if (isNamedMedium(m)) return NAMED_MEDIUM_INDEX[m].indexAt(lambdaNm);
  if (isSampledIndex(m)) return sampledIndexAt(m, lambdaNm);
  return filmIndexAt(m, lambdaNm);
}

/** n at λ of a medium used where light arrives from it (transparent there: its k is 0). */
export const transparentIndexAt = (m: Medium, lambdaNm: number): number => asComplex(mediumIndexAt(m, lambdaNm)).re;

/** Whether ñ depends on λ. */
export const isDispersiveMedium = (m: Medium): boolean =>
  isNamedMedium(m) || isSampledIndex(m) || (!isComplexConstant(m) && isDispersive(m));

/** Where `absorbsInBand` looks at k: every 5 nm of the colour band. */
const ABSORPTION_CHECK_STEP_NM = 5;

/**
 * Whether the medium absorbs (k > 0) anywhere in the colour band (DISPERSION_CHECK_NM, every 5 nm):
 * as an inside it is then opaque, T = 0 (docs/physics.md#absorbing-media).
 */
export function absorbsInBand(m: Medium): boolean {
  if (isComplexConstant(m)) return m.complex[1] > 0;
  if (isSampledIndex(m)) return m.sampled.some(([, , k]) => k > 0);
  if (!isNamedMedium(m)) return false;
  for (let l = DISPERSION_CHECK_NM.min; l <= DISPERSION_CHECK_NM.max; l += ABSORPTION_CHECK_STEP_NM)
    if (NAMED_MEDIUM_INDEX[m].indexAt(l).im > 0) return true;
  return false;
}

/** Where the medium's source gives values (null: at every λ). */
export const mediumRangeNm = (m: Medium): { readonly min: number; readonly max: number } | null =>
  isNamedMedium(m) ? NAMED_MEDIUM_INDEX[m].rangeNm : null;

/** The film at one wavelength. */
export const mediumStackAt = (stack: FilmStack<Medium>, lambdaNm: number): FilmStack<RefractiveIndex> => ({
  ...stack,
  nOutside: transparentIndexAt(stack.nOutside, lambdaNm),
  nFilm: mediumIndexAt(stack.nFilm, lambdaNm),
  nInside: mediumIndexAt(stack.nInside, lambdaNm),
});

/** The medium as URL, attribute and command line write it: `1.33`, `water`, `cauchy:1.45,6000`, `Au`, `complex:0.43,2.455`. */
export function mediumText(m: Medium): string {
  if (isComplexConstant(m)) return `complex:${m.complex[0]},${m.complex[1]}`;
  if (isSampledIndex(m)) return `sampled:${m.sampled.map(([l, n, k]) => `${l}:${n},${k}`).join(';')}`;
  return isNamedMedium(m) ? m : filmIndexText(m);
}

/** What a role accepts, as every refusal states it. */
export function mediumExpected(role: MediumRole): string {
  if (role === 'outside') return expectedNumber(FILM_STACK_DOMAIN.nOutside);
  const { n, k } = COMPLEX_INDEX_DOMAIN;
  return `${FILM_INDEX_EXPECTED}; ${NAMED_MEDIA.join(', ')}; or complex:n,k (ñ = n + ik, n in [${n.min}, ${n.max}], k in [${k.min}, ${k.max}])`;
}

/** The medium a text writes (`complex:n,k`, a name, or what parseFilmIndexText reads), whatever its range, or null. */
export function parseMediumText(text: string): Medium | null {
  if (isNamedMedium(text)) return text;
  if (text.startsWith('complex:')) {
    const parts = text.slice('complex:'.length).split(',').map(parseDecimal);
    return parts.length === 2 && parts.every(Number.isFinite) ? { complex: [parts[0]!, parts[1]!] } : null;
  }
  return parseFilmIndexText(text);
}

/** A cases file's value: what filmIndexFromJson reads, a named medium, or `{ "complex": [n, k] }`; null when none. */
export function mediumFromJson(value: unknown): Medium | null {
  if (isNamedMedium(value)) return value;
  const isObject = typeof value === 'object' && value !== null && !Array.isArray(value);
  if (isObject && Object.keys(value).join() === 'complex') {
    const nk = (value as { complex: unknown }).complex;
    const isPair = Array.isArray(nk) && nk.length === 2 && nk.every((t) => typeof t === 'number');
    return isPair ? { complex: [nk[0] as number, nk[1] as number] } : null;
  }
  return filmIndexFromJson(value);
}

/** What is wrong with a medium in a role (null: nothing), in words a message can quote. */
export function mediumProblem(m: Medium, role: MediumRole): string | null {
  if (role === 'outside') {
    const { min, max } = FILM_STACK_DOMAIN.nOutside;
    if (typeof m !== 'number') return 'the outside is transparent: a constant real index';
    return m >= min && m <= max ? null : `n is ${m}, outside [${min}, ${max}]`;
  }
  if (isComplexConstant(m)) {
    const [n, k] = m.complex;
    return complexIndexProblem({ re: n, im: k });
  }
  if (isSampledIndex(m)) return m.sampled.map(([, n, k]) => complexIndexProblem({ re: n, im: k })).find((p) => p !== null) ?? null;
  // A named medium's source keeps n and k inside COMPLEX_INDEX_DOMAIN over its range (a unit test holds every one).
  return isNamedMedium(m) ? null : filmIndexProblem(m);
}

/** Throws a ParameterError naming `name` when the medium is not allowed in its role. */
export function assertMedium(name: string, m: Medium, role: MediumRole): void {
  if (role !== 'outside' && !isNamedMedium(m) && !isComplexConstant(m) && !isSampledIndex(m)) return assertFilmIndex(name, m);
  const problem = mediumProblem(m, role);
  if (problem) throw new ParameterError(name, `${name}: ${mediumText(m)} is not allowed (${problem}); expected ${mediumExpected(role)}`);
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

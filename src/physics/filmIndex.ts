import { FILM_STACK_DOMAIN } from './filmReflectance.ts';
import { FILM_MATERIALS, type FilmMaterial, namedIndex } from './namedMedia.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from './spectralConventions.ts';
import { parseDecimal, quoted } from '../input/validate.ts';

/**
 * The film's refractive index n_b as a function of wavelength (docs/physics.md#a-dispersive-film):
 * - a number: the same at every wavelength (no dispersion);
 * - a named material (FILM_MATERIALS: the named media that are film indices, namedMedia.ts);
 * - a Cauchy film: n(λ) = A + B/λ² + C/λ⁴, λ in nm (B in nm², C in nm⁴).
 * Its domain: n(λ) within FILM_STACK_DOMAIN.nFilm (1–4) at every λ of 380–830 nm.
 */
export { FILM_MATERIALS, type FilmMaterial };
export interface CauchyFilm {
  /** [A, B, C]: n(λ) = A + B/λ² + C/λ⁴ with λ in nm */
  readonly cauchy: readonly [number, number, number];
}
export type FilmIndex = number | FilmMaterial | CauchyFilm;

/** Where n(λ) must stay within the index domain: the colour integral's band. */
export const DISPERSION_CHECK_NM = { min: LAMBDA_MIN_NM, max: LAMBDA_MAX_NM } as const;

export const FILM_INDEX_EXPECTED =
  `a number in [${FILM_STACK_DOMAIN.nFilm.min}, ${FILM_STACK_DOMAIN.nFilm.max}], ${FILM_MATERIALS.join(', ')}, ` +
  `or cauchy:A,B[,C] (n = A + B/λ² + C/λ⁴, λ in nm) within [${FILM_STACK_DOMAIN.nFilm.min}, ${FILM_STACK_DOMAIN.nFilm.max}] ` +
  `over ${DISPERSION_CHECK_NM.min}–${DISPERSION_CHECK_NM.max} nm`;

const isFilmMaterial = (text: string): text is FilmMaterial => (FILM_MATERIALS as readonly string[]).includes(text);

/** n_b at λ in nm. For a Cauchy film with B = C = 0 this is A exactly, as a number would be. */
export function filmIndexAt(index: FilmIndex, lambdaNm: number): number {
  if (typeof index === 'number') return index;
  if (typeof index === 'string') {
    const n = namedIndex(index)(lambdaNm);
    return typeof n === 'number' ? n : n.re;
  }
  const [a, b, c] = index.cauchy;
  const s = 1 / (lambdaNm * lambdaNm);
  return a + b * s + c * s * s;
}

/** Whether n_b depends on λ (a number does not; anything else is treated as dispersive). */
export const isDispersive = (index: FilmIndex): boolean => typeof index !== 'number';

/** The index as URL, attribute and command line write it: `1.33`, `water`, `cauchy:1.45,6000` (C left out when 0). */
export function filmIndexText(index: FilmIndex): string {
  if (typeof index !== 'object') return String(index);
  const [a, b, c] = index.cauchy;
  return `cauchy:${[a, b, ...(c === 0 ? [] : [c])].join(',')}`;
}

/**
 * The extremes of n(λ) over DISPERSION_CHECK_NM. For a Cauchy film n is a quadratic in s = 1/λ²,
 * so they lie at the ends or at its vertex s = −B/(2C).
 */
function indexExtremes(index: number | CauchyFilm): { lambdaNm: number; n: number }[] {
  const ends = [DISPERSION_CHECK_NM.min, DISPERSION_CHECK_NM.max];
  const at = (lambdaNm: number) => ({ lambdaNm, n: filmIndexAt(index, lambdaNm) });
  if (typeof index === 'number') return ends.map(at);
  const [, b, c] = index.cauchy;
  const sVertex = c === 0 ? -1 : -b / (2 * c);
  const [sMin, sMax] = [1 / DISPERSION_CHECK_NM.max ** 2, 1 / DISPERSION_CHECK_NM.min ** 2];
  return sVertex > sMin && sVertex < sMax ? [...ends.map(at), at(1 / Math.sqrt(sVertex))] : ends.map(at);
}

/**
 * What is wrong with an index (null: nothing), in words a message can quote. A named material is
 * within the domain over the band (a unit test holds each to it), so its data is not read here.
 */
export function filmIndexProblem(index: FilmIndex): string | null {
  const { min, max } = FILM_STACK_DOMAIN.nFilm;
  if (typeof index === 'string') return null;
  if (typeof index === 'object' && !index.cauchy.every(Number.isFinite)) return 'a Cauchy coefficient is not a finite number';
  for (const { lambdaNm, n } of indexExtremes(index)) {
    if (!(n >= min && n <= max)) {
      const where = typeof index === 'number' ? '' : ` at ${+lambdaNm.toFixed(1)} nm`;
      return `n${where} is ${+n.toPrecision(6)}, ${n < min ? `below ${min}` : `above ${max}`}`;
    }
  }
  return null;
}

/** The index a text writes (a number, a material's name or `cauchy:A,B[,C]`), whatever its range, or null. */
export function parseFilmIndexText(text: string): FilmIndex | null {
  if (isFilmMaterial(text)) return text;
  if (text.startsWith('cauchy:')) {
    const parts = text.slice('cauchy:'.length).split(',').map(parseDecimal);
    if ((parts.length !== 2 && parts.length !== 3) || !parts.every(Number.isFinite)) return null;
    return { cauchy: [parts[0]!, parts[1]!, parts[2] ?? 0] };
  }
  const n = parseDecimal(text);
  return Number.isFinite(n) ? n : null;
}

/** A cases file's `nFilm`: a number, a material's name, or `{ "cauchy": [A, B] }` / `[A, B, C]`; null when none of those. */
export function filmIndexFromJson(value: unknown): FilmIndex | null {
  if (typeof value === 'number') return value;
  if (typeof value === 'string') return isFilmMaterial(value) ? value : null;
  if (typeof value !== 'object' || value === null || Array.isArray(value) || Object.keys(value).join() !== 'cauchy') return null;
  const terms = (value as { cauchy: unknown }).cauchy;
  if (!Array.isArray(terms) || (terms.length !== 2 && terms.length !== 3) || !terms.every((t) => typeof t === 'number')) return null;
  return { cauchy: [terms[0] as number, terms[1] as number, terms[2] ?? 0] };
}

/** The checked index of a text, or why it is refused (quoting the text). */
export function readFilmIndex(text: string): { readonly index: FilmIndex } | { readonly problem: string } {
  const index = parseFilmIndexText(text);
  if (index === null) return { problem: `${quoted(text)} is not a number, a material or cauchy:A,B[,C]` };
  const problem = filmIndexProblem(index);
  return problem ? { problem } : { index };
}

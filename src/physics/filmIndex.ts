import { FILM_STACK_DOMAIN } from './filmReflectance.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from './spectralWeights.ts';
import { ParameterError, parseDecimal, quoted } from '../input/validate.ts';

/**
 * The film's refractive index n_b as a function of wavelength (docs/physics.md#a-dispersive-film):
 * - a number: the same at every wavelength (no dispersion);
 * - a named material (FILM_MATERIALS);
 * - a Cauchy film: n(λ) = A + B/λ² + C/λ⁴, λ in nm (B in nm², C in nm⁴).
 * Its domain: n(λ) within FILM_STACK_DOMAIN.nFilm (1–4) at every λ of 380–830 nm.
 */
export const FILM_MATERIALS = ['water'] as const;
export type FilmMaterial = (typeof FILM_MATERIALS)[number];
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

/**
 * Water at 20 °C: the four-term Sellmeier formula of M. Daimon and A. Masumura, "Measurement of
 * the refractive index of distilled water from the near-infrared region to the ultraviolet
 * region", Appl. Opt. 46, 3811–3820 (2007), their fit at 20.0 °C: n² − 1 = Σ K_i λ²/(λ² − L_i),
 * λ in µm, absolute (vacuum) index, valid 182–1129 nm.
 */
const WATER_20C_SELLMEIER = {
  k: [5.684027565e-1, 1.726177391e-1, 2.086189578e-2, 1.130748688e-1],
  lUm2: [5.101829712e-3, 1.821153936e-2, 2.620722293e-2, 1.069792721e1],
} as const;

/** n of water at 20 °C at λ in nm (Daimon and Masumura 2007). Domain: 182–1129 nm. */
export function waterIndex(lambdaNm: number): number {
  const x = (lambdaNm / 1000) ** 2;
  let n2 = 1;
  WATER_20C_SELLMEIER.k.forEach((k, i) => (n2 += (k * x) / (x - WATER_20C_SELLMEIER.lUm2[i]!)));
  return Math.sqrt(n2);
}

/** n_b at λ in nm. For a Cauchy film with B = C = 0 this is A exactly, as a number would be. */
export function filmIndexAt(index: FilmIndex, lambdaNm: number): number {
  if (typeof index === 'number') return index;
  if (index === 'water') return waterIndex(lambdaNm);
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
 * so they lie at the ends or at its vertex s = −B/(2C); water is monotonic there.
 */
function indexExtremes(index: FilmIndex): { lambdaNm: number; n: number }[] {
  const ends = [DISPERSION_CHECK_NM.min, DISPERSION_CHECK_NM.max];
  const at = (lambdaNm: number) => ({ lambdaNm, n: filmIndexAt(index, lambdaNm) });
  if (typeof index !== 'object') return ends.map(at);
  const [, b, c] = index.cauchy;
  const sVertex = c === 0 ? -1 : -b / (2 * c);
  const [sMin, sMax] = [1 / DISPERSION_CHECK_NM.max ** 2, 1 / DISPERSION_CHECK_NM.min ** 2];
  return sVertex > sMin && sVertex < sMax ? [...ends.map(at), at(1 / Math.sqrt(sVertex))] : ends.map(at);
}

/** What is wrong with an index (null: nothing), in words a message can quote. */
export function filmIndexProblem(index: FilmIndex): string | null {
  const { min, max } = FILM_STACK_DOMAIN.nFilm;
  if (typeof index === 'object' && !index.cauchy.every(Number.isFinite)) return 'a Cauchy coefficient is not a finite number';
  for (const { lambdaNm, n } of indexExtremes(index)) {
    if (!(n >= min && n <= max)) {
      const where = typeof index === 'number' ? '' : ` at ${+lambdaNm.toFixed(1)} nm`;
      return `n${where} is ${+n.toPrecision(6)}, ${n < min ? `below ${min}` : `above ${max}`}`;
    }
  }
  return null;
}

/** Throws a ParameterError naming `name` when the index is outside its domain. */
export function assertFilmIndex(name: string, index: FilmIndex): void {
  const problem = filmIndexProblem(index);
  if (problem)
    throw new ParameterError(name, `${name}: ${filmIndexText(index)} is not allowed (${problem}); expected ${FILM_INDEX_EXPECTED}`);
}

/** The index a text writes (a number, a material's name or `cauchy:A,B[,C]`), whatever its range, or null. */
export function parseFilmIndexText(text: string): FilmIndex | null {
  if ((FILM_MATERIALS as readonly string[]).includes(text)) return text as FilmMaterial;
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
  if (typeof value === 'string') return (FILM_MATERIALS as readonly string[]).includes(value) ? (value as FilmMaterial) : null;
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

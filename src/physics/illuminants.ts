import { CIE_D65, CIE_D65_START_NM, CIE_D65_STEP_NM } from './data/cieD65.ts';
import {
  CIE_DAYLIGHT_S0,
  CIE_DAYLIGHT_S1,
  CIE_DAYLIGHT_S2,
  CIE_DAYLIGHT_START_NM,
  CIE_DAYLIGHT_STEP_NM,
} from './data/cieDaylightComponents.ts';
import { ParameterError, assertInRange } from '../input/validate.ts';
import { DAYLIGHT_CCT_MAX_K, DAYLIGHT_CCT_MIN_K, ILLUMINANT_EXPECTED, type IlluminantSpec } from './illuminantSpec.ts';

/** Incident spectra I_in(λ) for eq (15), of the illuminants illuminantSpec.ts names and checks. */
export {
  DAYLIGHT_CCT_DOMAIN_K,
  DAYLIGHT_CCT_MAX_K,
  DAYLIGHT_CCT_MIN_K,
  ILLUMINANT_EXPECTED,
  type IlluminantSpec,
  NAMED_ILLUMINANTS,
  type NamedIlluminant,
  illuminantFromJson,
  illuminantKey,
  illuminantText,
  parseIlluminant,
} from './illuminantSpec.ts';

/** The c2 correction between the nominal and the current temperature scale. */
export const C2_CORRECTION = 1.4388 / 1.438;
const NOMINAL_CCT: Record<'D55' | 'D65' | 'D93', number> = { D55: 5500, D65: 6500, D93: 9300 };

/** The CCT (current scale) behind a daylight illuminant, or null for E and the D65 table. */
export function daylightCctOf(spec: IlluminantSpec): number | null {
  if (typeof spec === 'object') return spec.daylightCct;
  return spec in NOMINAL_CCT ? NOMINAL_CCT[spec as keyof typeof NOMINAL_CCT] * C2_CORRECTION : null;
}

/** Chromaticity of CIE daylight at a CCT, CIE 015:2018 eqs (4.7)–(4.9). Domain 4000–25000 K. */
export function daylightChromaticity(cctK: number): { x: number; y: number } {
  assertInRange('daylightCct', cctK, DAYLIGHT_CCT_MIN_K, DAYLIGHT_CCT_MAX_K, 'K');
  const t = cctK;
  const x =
    t <= 7000
      ? -4.607e9 / t ** 3 + 2.9678e6 / t ** 2 + 0.09911e3 / t + 0.244063
      : -2.0064e9 / t ** 3 + 1.9018e6 / t ** 2 + 0.24748e3 / t + 0.23704;
  return { x, y: -3 * x * x + 2.87 * x - 0.275 };
}

/**
 * The daylight weights M1, M2 of S(λ) = S0 + M1 S1 + M2 S2, CIE 015:2018 eq (4.10), rounded to
 * three decimals as CIE 015 prescribes (which reproduces the CIE's D65 table at 5 nm).
 */
export function daylightWeights(cctK: number): { m1: number; m2: number } {
  const { x, y } = daylightChromaticity(cctK);
  const m = 0.0241 + 0.2562 * x - 0.7341 * y;
  const round3 = (v: number) => Math.round(v * 1000) / 1000;
  return { m1: round3((-1.3515 - 1.7703 * x + 5.9114 * y) / m), m2: round3((0.03 - 31.4424 * x + 30.0717 * y) / m) };
}

/** Linear interpolation in a table sampled every `stepNm` from `startNm` (CIE's rule for daylight). */
export function interpolateTable(table: ArrayLike<number>, startNm: number, stepNm: number, lambdaNm: number): number {
  const u = (lambdaNm - startNm) / stepNm;
  const i = Math.min(Math.max(Math.floor(u), 0), table.length - 2);
  const f = u - i;
  return (table[i] as number) * (1 - f) + (table[i + 1] as number) * f;
}

/** I_in(λ) for an illuminant, in the CIE's relative units (100 at 560 nm for daylight). Domain 300–830 nm. */
export function illuminantSpd(spec: IlluminantSpec): (lambdaNm: number) => number {
  if (spec === 'E') return () => 1;
  if (spec === 'D65-table') return (l) => interpolateTable(CIE_D65, CIE_D65_START_NM, CIE_D65_STEP_NM, l);
  const cct = daylightCctOf(spec);
  if (cct === null) {
    throw new ParameterError('illuminant', `illuminant: ${JSON.stringify(spec)} is not allowed; expected ${ILLUMINANT_EXPECTED}`);
  }
  const { m1, m2 } = daylightWeights(cct);
  const at = (t: readonly number[], l: number) => interpolateTable(t, CIE_DAYLIGHT_START_NM, CIE_DAYLIGHT_STEP_NM, l);
  return (l) => at(CIE_DAYLIGHT_S0, l) + m1 * at(CIE_DAYLIGHT_S1, l) + m2 * at(CIE_DAYLIGHT_S2, l);
}

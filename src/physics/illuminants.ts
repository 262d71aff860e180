import { CIE_D65, CIE_D65_START_NM, CIE_D65_STEP_NM } from './data/cieD65.ts';
import {
  CIE_DAYLIGHT_S0,
  CIE_DAYLIGHT_S1,
  CIE_DAYLIGHT_S2,
  CIE_DAYLIGHT_START_NM,
  CIE_DAYLIGHT_STEP_NM,
} from './data/cieDaylightComponents.ts';
import { CIE_LAMPS, CIE_LAMPS_START_NM, CIE_LAMPS_STEP_NM } from './data/cieLamps.ts';
import {
  MALLETT2019_BLUE,
  MALLETT2019_GREEN,
  MALLETT2019_RED,
  MALLETT2019_START_NM,
  MALLETT2019_STEP_NM,
} from './data/mallett2019Basis.ts';
import { SODIUM_D_LINES } from './lightLines.ts';
import { type LightTint, WHITE_TINT, isWhiteTint } from './lightTint.ts';
import { interpolateTable } from './tableInterpolation.ts';
import { ParameterError, assertInRange } from '../input/validate.ts';
import {
  DAYLIGHT_CCT_MAX_K,
  DAYLIGHT_CCT_MIN_K,
  type IlluminantSpec,
  LAMP_NAMES,
  type LampName,
  type NamedIlluminant,
  illuminantLines,
} from './illuminantSpec.ts';

/**
 * Incident spectra I_in(λ) for eq (15), of the lights illuminantSpec.ts names and checks.
 * **CCT convention** of the daylights: CIE's D65 is 6504 K because the nominal temperatures
 * predate the 1968 change of the radiation constant c2 from 1.4380e-2 to 1.4388e-2 m·K; the same
 * factor 1.4388/1.4380 applies to every nominal temperature (5500 → 5503 K, 6500 → 6504 K,
 * 9300 → 9305 K). The lamps are the CIE's tables every 5 nm over 380–780 nm (data/cieLamps.ts),
 * linear between rows and held at the end rows' values outside them.
 */
export {
  DAYLIGHT_CCT_DOMAIN_K,
  DAYLIGHT_CCT_MAX_K,
  DAYLIGHT_CCT_MIN_K,
  ILLUMINANT_EXPECTED,
  type IlluminantSpec,
  LAMP_NAMES,
  type LampName,
  NAMED_ILLUMINANTS,
  type NamedIlluminant,
  illuminantFromJson,
  illuminantKey,
  illuminantLines,
  illuminantText,
  listedNames,
  parseIlluminant,
} from './illuminantSpec.ts';

/** The c2 correction between the nominal and the current temperature scale. */
export const C2_CORRECTION = 1.4388 / 1.438;
const NOMINAL_CCT: Record<'D55' | 'D65' | 'D93', number> = { D55: 5500, D65: 6500, D93: 9300 };

/** What a named daylight is: its CCT on the current scale and its nominal one. */
const daylightAbout = (name: keyof typeof NOMINAL_CCT): string =>
  `CIE daylight at ${Math.round(NOMINAL_CCT[name] * C2_CORRECTION)} K (the nominal ${NOMINAL_CCT[name]} K on the current c2)`;

/** What a lamp is, by its name's family (data/cieLamps.ts). */
function lampAbout(name: LampName): string {
  const fl = /^FL(\d+)$/.exec(name);
  if (fl) {
    const n = Number(fl[1]);
    return `CIE fluorescent lamp, ${n <= 6 ? 'standard' : n <= 9 ? 'broadband' : 'three-band'} (CIE 15:2004 tables)`;
  }
  const kind = { B: 'phosphor on blue', BH: 'phosphor on blue with red', RGB: 'red, green and blue chips', V: 'phosphor on violet' };
  return `CIE LED, ${kind[/^LED-([A-Z]+)/.exec(name)![1] as keyof typeof kind]} (CIE 015:2018 tables)`;
}

/** What each light is, by name (the colour tool's help lists it); its names are illuminantSpec.ts's. */
export const LIGHT_ABOUT = {
  D55: daylightAbout('D55'),
  D65: daylightAbout('D65'),
  D93: daylightAbout('D93'),
  E: 'equal energy',
  'D65-table': "the CIE's tabulated D65 (ISO 11664-2)",
  ...(Object.fromEntries(LAMP_NAMES.map((name) => [name, lampAbout(name)])) as Record<LampName, string>),
  Na: `low-pressure sodium, its D lines at ${SODIUM_D_LINES.map((l) => l.nm).join(' and ')} nm, powers ${SODIUM_D_LINES.map((l) => l.power).join(' : ')}`,
} as const satisfies Readonly<Record<NamedIlluminant, string>>;
/** The CCT (current scale) behind a daylight illuminant, or null for the others. */
export function daylightCctOf(spec: IlluminantSpec): number | null {
  if (typeof spec === 'object') return 'daylightCct' in spec ? spec.daylightCct : null;
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

/** A table every `stepNm` from `startNm`, linear between rows and held at its end rows' values outside them. */
function heldTable(table: readonly number[], startNm: number, stepNm: number): (lambdaNm: number) => number {
  const endNm = startNm + (table.length - 1) * stepNm;
  return (l) => interpolateTable(table, startNm, stepNm, Math.min(Math.max(l, startNm), endNm));
}

const isLamp = (spec: IlluminantSpec): spec is LampName => typeof spec === 'string' && Object.hasOwn(CIE_LAMPS, spec);

/**
 * I_in(λ) for an illuminant with a spectrum, in the CIE's relative units (100 at 560 nm for
 * daylight). Domain 300–830 nm. A line source has no spectrum (illuminantLines): a ParameterError.
 */
export function illuminantSpd(spec: IlluminantSpec): (lambdaNm: number) => number {
  if (spec === 'E') return () => 1;
  if (spec === 'D65-table') return (l) => interpolateTable(CIE_D65, CIE_D65_START_NM, CIE_D65_STEP_NM, l);
  if (isLamp(spec)) return heldTable(CIE_LAMPS[spec], CIE_LAMPS_START_NM, CIE_LAMPS_STEP_NM);
  const cct = daylightCctOf(spec);
  if (cct === null) {
    throw new ParameterError(
      'illuminant',
      `illuminant: ${JSON.stringify(spec)} has no spectrum; expected a light other than a line source`,
    );
  }
  const { m1, m2 } = daylightWeights(cct);
  const at = (t: readonly number[], l: number) => interpolateTable(t, CIE_DAYLIGHT_START_NM, CIE_DAYLIGHT_STEP_NM, l);
  return (l) => at(CIE_DAYLIGHT_S0, l) + m1 * at(CIE_DAYLIGHT_S1, l) + m2 * at(CIE_DAYLIGHT_S2, l);
}

/**
 * The spectrum of a tint (R, G, B) by Mallett and Yuksel's sRGB basis (data/mallett2019Basis.ts):
 * R·r(λ) + G·g(λ) + B·b(λ), each basis spectrum linear between its 5 nm rows and held at its end
 * rows' values outside 380–780 nm. A light's spectrum times this is the tinted light's. The white
 * tint is 1 exactly: the published basis sums to 1 only within 1e-5, and an untinted light is the illuminant.
 */
export function tintSpectrum(tint: LightTint): (lambdaNm: number) => number {
  if (isWhiteTint(tint)) return () => 1;
  const [r, g, b] = ([0, 1, 2] as const).map(basisSpectrum);
  return (l) => tint[0] * r!(l) + tint[1] * g!(l) + tint[2] * b!(l);
}

/** Which of the basis spectra: 0 red, 1 green, 2 blue. */
export type BasisIndex = 0 | 1 | 2;

/** Basis spectrum j of Mallett and Yuksel's sRGB basis, as tintSpectrum reads it (the tint of colour e_j). */
export const basisSpectrum = (j: BasisIndex): ((lambdaNm: number) => number) =>
  heldTable([MALLETT2019_RED, MALLETT2019_GREEN, MALLETT2019_BLUE][j]!, MALLETT2019_START_NM, MALLETT2019_STEP_NM);

/**
 * The light as a plot draws it on a 1 nm grid: its spectrum, or each line as a triangle 1 nm wide
 * on each side whose height is its power (its share of each grid point, by linear interpolation);
 * either times the spectrum of its tint.
 */
export function illuminantDrawn(spec: IlluminantSpec, tint: LightTint = WHITE_TINT): (lambdaNm: number) => number {
  const lines = illuminantLines(spec);
  const t = tintSpectrum(tint);
  if (lines === null) {
    const spd = illuminantSpd(spec);
    return (l) => spd(l) * t(l);
  }
  return (l) => lines.reduce((sum, line) => sum + line.power * t(line.nm) * Math.max(0, 1 - Math.abs(l - line.nm)), 0);
}

import { CIE_D65, CIE_D65_START_NM, CIE_D65_STEP_NM } from './data/cieD65.ts';
import {
  CIE_DAYLIGHT_S0,
  CIE_DAYLIGHT_S1,
  CIE_DAYLIGHT_S2,
  CIE_DAYLIGHT_START_NM,
  CIE_DAYLIGHT_STEP_NM,
} from './data/cieDaylightComponents.ts';
import { CIE_LAMPS, CIE_LAMPS_START_NM, CIE_LAMPS_STEP_NM } from './data/cieLamps.ts';
import { LINE_EXPECTED, LINE_PREFIX, SODIUM_D_LINES, type SpectralLine, parseLineNm } from './lightLines.ts';
import { type NumberDomain, ParameterError, assertInRange, isInDomain, parseDecimal, rejectValue } from '../input/validate.ts';

/** The CIE's lamps by name (data/cieLamps.ts: FL1–FL12, the CIE 15:2018 LEDs). */
export type LampName = keyof typeof CIE_LAMPS;
const LAMP_NAMES = Object.keys(CIE_LAMPS) as LampName[];

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

/**
 * Incident spectra I_in(λ) for eq (15), by name, each with what it is (the colour tool's help lists
 * it): the registry every interface's list of lights derives from (the panel, the catalogues'
 * labels, the URL's and the colour tool's messages).
 * - `D55`, `D65`, `D93`: CIE daylight from the S0/S1/S2 basis (CIE 015:2018 §4.1) at the paper's
 *   nominal 5500, 6500 and 9300 K. **CCT convention**: CIE's D65 is 6504 K because the nominal
 *   temperatures predate the 1968 change of the radiation constant c2 from 1.4380e-2 to
 *   1.4388e-2 m·K; we apply the same factor 1.4388/1.4380 to every nominal temperature
 *   (5500 → 5503 K, 6500 → 6504 K, 9300 → 9305 K). `{ daylightCct }` takes a CCT as it is
 *   (already on the current scale), 4000–25000 K.
 * - `D65-table`: the CIE's tabulated D65 (ISO 11664-2).
 * - `E`: equal energy, 1 at every λ.
 * - `FL1`–`FL12`, `LED-B1` … `LED-V2`: the CIE's lamps as tabulated every 5 nm over 380–780 nm
 *   (data/cieLamps.ts), linear between rows and held at the end rows' values outside them.
 * - `Na`: low-pressure sodium's D doublet, a line source (lightLines.ts); `{ lineNm }` (text
 *   `line:NM`) is one line at NM nm.
 */
export const NAMED_LIGHTS = {
  D55: daylightAbout('D55'),
  D65: daylightAbout('D65'),
  D93: daylightAbout('D93'),
  E: 'equal energy',
  'D65-table': "the CIE's tabulated D65 (ISO 11664-2)",
  ...(Object.fromEntries(LAMP_NAMES.map((name) => [name, lampAbout(name)])) as Record<LampName, string>),
  Na: `low-pressure sodium, its D lines at ${SODIUM_D_LINES.map((l) => l.nm).join(' and ')} nm, powers ${SODIUM_D_LINES.map((l) => l.power).join(' : ')}`,
} as const satisfies Readonly<Record<string, string>>;
export type NamedIlluminant = keyof typeof NAMED_LIGHTS;
/** The lights by name, in the registry's order. */
export const NAMED_ILLUMINANTS = Object.keys(NAMED_LIGHTS) as readonly NamedIlluminant[];
export type IlluminantSpec = NamedIlluminant | { readonly daylightCct: number } | { readonly lineNm: number };

export const DAYLIGHT_CCT_MIN_K = 4000;
export const DAYLIGHT_CCT_MAX_K = 25000;
export const DAYLIGHT_CCT_DOMAIN_K: NumberDomain = { min: DAYLIGHT_CCT_MIN_K, max: DAYLIGHT_CCT_MAX_K, unit: 'K' };
/**
 * Names as a message lists them: a run of three or more that differ only by a number counting up
 * by one (FL1, FL2, …, FL12) as its first and last, `FL1–FL12`.
 */
export function listedNames(names: readonly string[]): string {
  const numbered = names.map((name) => /^(.*?)(\d+)$/.exec(name));
  const follows = (k: number): boolean => {
    const [before, after] = [numbered[k - 1], numbered[k]];
    return !!before && !!after && before[1] === after[1] && Number(after[2]) === Number(before[2]) + 1;
  };
  const listed: string[] = [];
  for (let i = 0; i < names.length;) {
    let j = i;
    while (j + 1 < names.length && follows(j + 1)) j++;
    const run = j - i >= 2;
    listed.push(run ? `${names[i]}–${names[j]}` : names[i]!);
    i = run ? j + 1 : i + 1;
  }
  return listed.join(', ');
}

/** What an illuminant may be, as every message (URL, element, CLI, this module) states it. */
export const ILLUMINANT_EXPECTED = `one of ${listedNames(NAMED_ILLUMINANTS)}, ${LINE_EXPECTED}, or a daylight CCT in [${DAYLIGHT_CCT_MIN_K}, ${DAYLIGHT_CCT_MAX_K}] K`;

const isNamed = (text: unknown): text is NamedIlluminant => (NAMED_ILLUMINANTS as readonly unknown[]).includes(text);

/** A name or `line:NM` (the text both forms share); null when neither. */
function namedOrLine(text: string): IlluminantSpec | null {
  if (isNamed(text)) return text;
  const lineNm = parseLineNm(text);
  return lineNm === null ? null : { lineNm };
}

/**
 * An illuminant as a JSON value (cases files, the material's options): a name, `line:NM`, or
 * exactly `{ daylightCct: K }` in the CCT's domain; anything else is a ParameterError naming `field`.
 */
export function illuminantFromJson(value: unknown, field = 'illuminant'): IlluminantSpec {
  const named = typeof value === 'string' ? namedOrLine(value) : null;
  if (named !== null) return named;
  const isObject = typeof value === 'object' && value !== null && !Array.isArray(value);
  if (isObject && Object.keys(value).join() === 'daylightCct') {
    const cct = (value as { daylightCct: unknown }).daylightCct;
    if (isInDomain(cct, DAYLIGHT_CCT_DOMAIN_K)) return { daylightCct: cct };
  }
  return rejectValue(field, value, ILLUMINANT_EXPECTED);
}

/** An illuminant as text (URL, attribute, command line): a name, `line:NM`, or a CCT in kelvin; null when none. */
export function parseIlluminant(text: string): IlluminantSpec | null {
  const named = namedOrLine(text);
  if (named !== null) return named;
  const cct = parseDecimal(text);
  return isInDomain(cct, DAYLIGHT_CCT_DOMAIN_K) ? { daylightCct: cct } : null;
}

/** An illuminant as text: its name, `line:NM`, or its CCT in kelvin (what `parseIlluminant` reads back). */
export const illuminantText = (i: IlluminantSpec): string =>
  typeof i !== 'object' ? i : 'lineNm' in i ? `${LINE_PREFIX}${i.lineNm}` : String(i.daylightCct);

/** The lines of a line source (`Na`, `{ lineNm }`), or null for a light with a spectrum. */
export function illuminantLines(spec: IlluminantSpec): readonly SpectralLine[] | null {
  if (spec === 'Na') return SODIUM_D_LINES;
  return typeof spec === 'object' && 'lineNm' in spec ? [{ nm: spec.lineNm, power: 1 }] : null;
}

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

/** Linear interpolation in a table sampled every `stepNm` from `startNm` (CIE's rule for daylight). */
export function interpolateTable(table: ArrayLike<number>, startNm: number, stepNm: number, lambdaNm: number): number {
  const u = (lambdaNm - startNm) / stepNm;
  const i = Math.min(Math.max(Math.floor(u), 0), table.length - 2);
  const f = u - i;
  return (table[i] as number) * (1 - f) + (table[i + 1] as number) * f;
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
 * The light as a plot draws it on a 1 nm grid: its spectrum, or each line as a triangle 1 nm wide
 * on each side whose height is its power (its share of each grid point, by linear interpolation).
 */
export function illuminantDrawn(spec: IlluminantSpec): (lambdaNm: number) => number {
  const lines = illuminantLines(spec);
  if (lines === null) return illuminantSpd(spec);
  return (l) => lines.reduce((sum, line) => sum + line.power * Math.max(0, 1 - Math.abs(l - line.nm)), 0);
}

/** A short stable name for an illuminant, for cache keys and output. */
export const illuminantKey = (spec: IlluminantSpec): string =>
  typeof spec !== 'object' ? spec : 'lineNm' in spec ? `line-${spec.lineNm}nm` : `daylight-${spec.daylightCct}K`;

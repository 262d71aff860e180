import { type NumberDomain, isInDomain, parseDecimal, rejectValue } from '../input/validate.ts';
import { LINE_DOMAIN_NM, LINE_EXPECTED, LINE_PREFIX, SODIUM_D_LINES, type SpectralLine, parseLineNm } from './lightLines.ts';

/**
 * The lights by name, and how each is checked and written, apart from their spectra
 * (illuminants.ts holds those and the tables behind them), so checking a light loads no data.
 * - `D55`, `D65`, `D93`: CIE daylight at the paper's nominal 5500, 6500 and 9300 K; `{ daylightCct }`
 *   takes a CCT as it is (already on the current scale), 4000–25000 K.
 * - `E`: equal energy; `D65-table`: the CIE's tabulated D65 (ISO 11664-2).
 * - `FL1`–`FL12`, `LED-B1` … `LED-V2`: the CIE's lamps (data/cieLamps.ts, whose rows these names key).
 * - `Na`: low-pressure sodium's D doublet, a line source (lightLines.ts); `{ lineNm }` (text
 *   `line:NM`) is one line at NM nm.
 */
export const LAMP_NAMES = [
  'FL1',
  'FL2',
  'FL3',
  'FL4',
  'FL5',
  'FL6',
  'FL7',
  'FL8',
  'FL9',
  'FL10',
  'FL11',
  'FL12',
  'LED-B1',
  'LED-B2',
  'LED-B3',
  'LED-B4',
  'LED-B5',
  'LED-BH1',
  'LED-RGB1',
  'LED-V1',
  'LED-V2',
] as const;
export type LampName = (typeof LAMP_NAMES)[number];
/** Every light by name, in the order every interface lists them. */
export const NAMED_ILLUMINANTS = ['D55', 'D65', 'D93', 'E', 'D65-table', ...LAMP_NAMES, 'Na'] as const;
export type NamedIlluminant = (typeof NAMED_ILLUMINANTS)[number];
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
 * exactly `{ daylightCct: K }` or `{ lineNm: NM }` (the IlluminantSpec it reads as) in its domain;
 * anything else is a ParameterError naming `field`.
 */
export function illuminantFromJson(value: unknown, field = 'illuminant'): IlluminantSpec {
  const named = typeof value === 'string' ? namedOrLine(value) : null;
  if (named !== null) return named;
  const isObject = typeof value === 'object' && value !== null && !Array.isArray(value);
  const only = isObject ? Object.keys(value).join() : '';
  const number = isObject ? (value as Record<string, unknown>)[only] : undefined;
  if (only === 'daylightCct' && isInDomain(number, DAYLIGHT_CCT_DOMAIN_K)) return { daylightCct: number };
  if (only === 'lineNm' && isInDomain(number, LINE_DOMAIN_NM)) return { lineNm: number };
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

/** A short stable name for an illuminant, for cache keys and output. */
export const illuminantKey = (spec: IlluminantSpec): string =>
  typeof spec !== 'object' ? spec : 'lineNm' in spec ? `line-${spec.lineNm}nm` : `daylight-${spec.daylightCct}K`;

/** The lines of a line source (`Na`, `{ lineNm }`), or null for a light with a spectrum. */
export function illuminantLines(spec: IlluminantSpec): readonly SpectralLine[] | null {
  if (spec === 'Na') return SODIUM_D_LINES;
  return typeof spec === 'object' && 'lineNm' in spec ? [{ nm: spec.lineNm, power: 1 }] : null;
}

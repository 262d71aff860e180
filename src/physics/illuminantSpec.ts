import { type NumberDomain, isInDomain, parseDecimal, rejectValue } from '../input/validate.ts';

/**
 * Incident spectra I_in(λ) for eq (15).
 * - `D55`, `D65`, `D93`: CIE daylight from the S0/S1/S2 basis (CIE 015:2018 §4.1) at the paper's
 *   nominal 5500, 6500 and 9300 K. **CCT convention**: CIE's D65 is 6504 K because the nominal
 *   temperatures predate the 1968 change of the radiation constant c2 from 1.4380e-2 to
 *   1.4388e-2 m·K; we apply the same factor 1.4388/1.4380 to every nominal temperature
 *   (5500 → 5503 K, 6500 → 6504 K, 9300 → 9305 K). `{ daylightCct }` takes a CCT as it is
 *   (already on the current scale), 4000–25000 K.
 * - `D65-table`: the CIE's tabulated D65 (ISO 11664-2).
 * - `E`: equal energy, 1 at every λ.
 */
export const NAMED_ILLUMINANTS = ['D55', 'D65', 'D93', 'E', 'D65-table'] as const;
export type NamedIlluminant = (typeof NAMED_ILLUMINANTS)[number];
export type IlluminantSpec = NamedIlluminant | { readonly daylightCct: number };

export const DAYLIGHT_CCT_MIN_K = 4000;
export const DAYLIGHT_CCT_MAX_K = 25000;
export const DAYLIGHT_CCT_DOMAIN_K: NumberDomain = { min: DAYLIGHT_CCT_MIN_K, max: DAYLIGHT_CCT_MAX_K, unit: 'K' };
/** What an illuminant may be, as every message (URL, element, CLI, this module) states it. */
export const ILLUMINANT_EXPECTED = `one of ${NAMED_ILLUMINANTS.join(', ')} or a daylight CCT in [${DAYLIGHT_CCT_MIN_K}, ${DAYLIGHT_CCT_MAX_K}] K`;
/**
 * An illuminant as a JSON value (cases files, the material's options): a name, or exactly
 * `{ daylightCct: K }` in the CCT's domain; anything else is a ParameterError naming `field`.
 */
export function illuminantFromJson(value: unknown, field = 'illuminant'): IlluminantSpec {
  if (typeof value === 'string' && (NAMED_ILLUMINANTS as readonly string[]).includes(value)) return value as NamedIlluminant;
  const isObject = typeof value === 'object' && value !== null && !Array.isArray(value);
  if (isObject && Object.keys(value).join() === 'daylightCct') {
    const cct = (value as { daylightCct: unknown }).daylightCct;
    if (isInDomain(cct, DAYLIGHT_CCT_DOMAIN_K)) return { daylightCct: cct };
  }
  return rejectValue(field, value, ILLUMINANT_EXPECTED);
}

/** An illuminant as text (URL, attribute, command line): a name, or a CCT in kelvin; null when neither. */
export function parseIlluminant(text: string): IlluminantSpec | null {
  if ((NAMED_ILLUMINANTS as readonly string[]).includes(text)) return text as NamedIlluminant;
  const cct = parseDecimal(text);
  return isInDomain(cct, DAYLIGHT_CCT_DOMAIN_K) ? { daylightCct: cct } : null;
}

/** An illuminant as text: its name, or its CCT in kelvin (what `parseIlluminant` reads back). */
export const illuminantText = (i: IlluminantSpec): string => (typeof i === 'object' ? String(i.daylightCct) : i);

/** A short stable name for an illuminant, for cache keys and output. */
export const illuminantKey = (spec: IlluminantSpec): string => (typeof spec === 'object' ? `daylight-${spec.daylightCct}K` : spec);

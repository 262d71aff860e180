/**
 * Input checks shared by every entry point. A bad value throws a RangeError whose message names
 * the parameter, the value and the allowed range, before anything is computed with it.
 */
export class ParameterError extends RangeError {
  constructor(
    readonly parameter: string,
    message: string,
  ) {
    super(message);
    this.name = 'ParameterError';
  }
}

/** How many characters of a bad value a message repeats before cutting it short (URL, element, CLI). */
export const MAX_ECHOED_CHARS = 40;

/** `text` cut to `max` characters, saying how long it was when cut. */
export function shorten(text: string, max = MAX_ECHOED_CHARS): string {
  return text.length <= max ? text : `${text.slice(0, max)}… (${text.length} characters)`;
}

/** A text as a message repeats it: quoted as JSON (a newline cannot break the line), cut short when long. */
export function quoted(text: string, max = MAX_ECHOED_CHARS): string {
  return text.length <= max ? JSON.stringify(text) : `${JSON.stringify(text.slice(0, max))}… (${text.length} characters)`;
}

/** A closed interval of allowed numbers, with its unit for messages ('' for none). */
export interface NumberDomain {
  readonly min: number;
  readonly max: number;
  readonly unit: string;
}

/** "a number in [min, max] unit", as every message states a range. */
export const expectedNumber = (d: NumberDomain): string => `a number in [${d.min}, ${d.max}]${d.unit ? ` ${d.unit}` : ''}`;

export const isInDomain = (value: unknown, d: NumberDomain): value is number =>
  typeof value === 'number' && Number.isFinite(value) && value >= d.min && value <= d.max;

/**
 * Plain decimal notation, optionally with an exponent. `Number()` alone would also accept "",
 * "  7 ", "0x1f", "0b11" and "Infinity"; none of those is a thickness or an angle.
 */
const DECIMAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

/** The longest text read as one number; longer is certainly a mistake. */
const MAX_NUMBER_CHARS = 32;

/** The finite number `text` writes in plain decimal notation, or NaN ("12abc", "", "1e999"). */
export function parseDecimal(text: string): number {
  const value = text.length <= MAX_NUMBER_CHARS && DECIMAL.test(text) ? Number(text) : Number.NaN;
  return Number.isFinite(value) ? value : Number.NaN;
}

export function assertInRange(name: string, value: number, min: number, max: number, unit = ''): void {
  if (!isInDomain(value, { min, max, unit })) {
    throw new ParameterError(name, `${name}: ${String(value)} is not allowed; expected ${expectedNumber({ min, max, unit })}`);
  }
}

/*
 * How bad input becomes an error, at every entry point (URL, element, material, command lines):
 * one line of the form "<field>: <value> is not allowed; expected <what is allowed>", with the
 * value written as JSON (so a newline in it cannot break the line) and cut short when long.
 */

/** A value as it appears in an error message: numbers as written, anything else as JSON. */
export function describeValue(value: unknown): string {
  if (typeof value === 'number') return String(value);
  if (value === undefined) return 'no value';
  if (typeof value === 'string') return quoted(value);
  // JSON for everything the tool reads (JSON values); a symbol or function says its type instead.
  return shorten(JSON.stringify(value) ?? typeof value);
}

export function rejectValue(field: string, value: unknown, expected: string): never {
  throw new ParameterError(field, `${field}: ${describeValue(value)} is not allowed; expected ${expected}`);
}

/** `value` if it is one of the `allowed` strings; otherwise a ParameterError naming `field`. */
export function oneOf<T extends string>(field: string, value: unknown, allowed: readonly T[]): T {
  if (typeof value === 'string' && (allowed as readonly string[]).includes(value)) return value as T;
  return rejectValue(field, value, `one of ${allowed.join(', ')}`);
}

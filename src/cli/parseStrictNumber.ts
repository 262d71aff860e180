import { rejectValue } from './inputErrors.ts';

/**
 * Plain decimal notation, optionally with an exponent. `Number()` alone would also accept "",
 * "  7 ", "0x1f", "0b11" and "Infinity"; none of those is a thickness or an angle.
 */
const DECIMAL = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

/** The longest text read as one number; longer is certainly a mistake. */
export const MAX_NUMBER_CHARS = 32;

/**
 * The finite number written in `text`, or a ParameterError naming `field` and saying what is
 * `expected` ("12abc", "", "NaN", "1e999" are all errors). Range checks are the caller's.
 */
export function parseStrictNumber(field: string, text: string, expected: string): number {
  const value = text.length <= MAX_NUMBER_CHARS && DECIMAL.test(text) ? Number(text) : Number.NaN;
  if (!Number.isFinite(value)) rejectValue(field, text, expected);
  return value;
}

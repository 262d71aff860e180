import { parseDecimal, rejectValue } from '../input/validate.ts';

/**
 * The finite number written in `text` (plain decimal, see `parseDecimal`), or a ParameterError
 * naming `field` and saying what is `expected` ("12abc", "", "NaN", "1e999" are all errors).
 * Range checks are the caller's.
 */
export function parseStrictNumber(field: string, text: string, expected: string): number {
  const value = parseDecimal(text);
  return Number.isNaN(value) ? rejectValue(field, text, expected) : value;
}

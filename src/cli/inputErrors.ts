import { ParameterError, quoted, shorten } from '../physics/validate.ts';

/**
 * How bad input becomes an error. Every message is one line of the form
 * "<field>: <value> is not allowed; expected <what is allowed>", with the value written as JSON
 * (so a newline in it cannot break the line) and cut short when long.
 */

/** A file path as it appears in an error message: quoted, cut only when absurd. */
export const describePath = (path: string): string => shorten(JSON.stringify(path), 200);

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

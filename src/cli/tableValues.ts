import { isInDomain, type NumberDomain, ParameterError, rejectValue, expectedNumber } from '../input/validate.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';

/** A table longer than this is a typo (a step of 0.001 instead of 10), not a lesson. */
export const MAX_TABLE_ROWS = 100_000;

/** The flag names a range's errors are reported under. */
export interface RangeNames {
  readonly from: string;
  readonly to: string;
  readonly step: string;
}

/**
 * from, from + step, …, up to and including `to` where the step lands on it (to within 1e-9 of a
 * step). Each value is from + i·step rounded to 12 significant digits, so steps of 0.1 give 0.3
 * rather than 0.30000000000000004. The row count is checked before anything is allocated.
 */
export function evenlySpaced(from: number, to: number, step: number, names: RangeNames): number[] {
  if (!(to >= from)) rejectValue(names.to, to, `a number ≥ the start of the range (${from})`);
  if (!(step > 0)) rejectValue(names.step, step, 'a number > 0');
  const count = Math.floor((to - from) / step + 1e-9) + 1;
  if (count > MAX_TABLE_ROWS) {
    throw new ParameterError(
      names.step,
      `${names.step}: ${step} is not allowed; it gives ${count} rows from ${from} to ${to}, expected at most ${MAX_TABLE_ROWS}`,
    );
  }
  return Array.from({ length: count }, (_, i) => Math.min(to, Math.max(from, Number((from + i * step).toPrecision(12)))));
}

/** The values of a range given as three texts, each end inside `domain`. */
export function parseRange(texts: RangeNames, domain: NumberDomain, names: RangeNames): number[] {
  const end = (key: 'from' | 'to'): number => {
    const value = parseStrictNumber(names[key], texts[key], expectedNumber(domain));
    return isInDomain(value, domain) ? value : rejectValue(names[key], value, expectedNumber(domain));
  };
  const step = parseStrictNumber(names.step, texts.step, `a number > 0${domain.unit ? ` ${domain.unit}` : ''}`);
  return evenlySpaced(end('from'), end('to'), step, names);
}

/** "FROM:TO:STEP" (as in `--angles 0:85:5`) → its values, each inside `domain`. */
export function parseColonRange(flag: string, text: string, domain: NumberDomain): number[] {
  const parts = text.split(':');
  const [from, to, step] = parts;
  if (parts.length !== 3 || from === undefined || to === undefined || step === undefined) {
    return rejectValue(flag, text, `FROM:TO:STEP with FROM and TO in [${domain.min}, ${domain.max}] ${domain.unit}, e.g. 0:85:5`);
  }
  return parseRange({ from, to, step }, domain, { from: flag, to: flag, step: flag });
}

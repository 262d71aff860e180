import { ParameterError, rejectValue, shorten } from '../input/validate.ts';
import { describePath } from './inputErrors.ts';
import { jsonNestingDepth } from './jsonNestingDepth.ts';

/** More entries than this in one file is a mistake, not a workload. */
export const MAX_CASES = 100_000;

/**
 * The deepest nesting a cases file may have. A valid one needs 3 levels (the array, a case, its
 * `illuminant` object or `wavelengthsNm` array); the rest is room for a file a later version
 * writes, and far below what would exhaust the parser's or the printer's stack.
 */
export const MAX_CASES_NESTING_DEPTH = 16;

/**
 * The entries of a `--cases` file (the colour tool's cases, the render command's views): a JSON
 * array of at most MAX_CASES entries, unchecked. A text nested deeper than MAX_CASES_NESTING_DEPTH
 * is refused before it is parsed. `fileName` is only for messages; `what` names the entries in them.
 */
export function parseJsonArray(text: string, fileName: string, what: string): unknown[] {
  const depth = jsonNestingDepth(text);
  if (depth > MAX_CASES_NESTING_DEPTH) {
    const message =
      `--cases: ${describePath(fileName)} is malformed: its arrays and objects nest ${depth} deep; ` +
      `expected at most ${MAX_CASES_NESTING_DEPTH} levels (a JSON array of ${what})`;
    throw new ParameterError('--cases', message);
  }
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (error) {
    const reason = shorten(error instanceof Error ? error.message : String(error), 80);
    const message = `--cases: ${describePath(fileName)} is not valid JSON (${reason}); expected a JSON array of ${what}`;
    throw new ParameterError('--cases', message);
  }
  if (!Array.isArray(data)) return rejectValue('--cases', data, `a JSON array of ${what}`);
  if (data.length > MAX_CASES) {
    throw new ParameterError('--cases', `--cases: ${data.length} ${what} is not allowed; expected at most ${MAX_CASES}`);
  }
  return data;
}

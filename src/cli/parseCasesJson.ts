import { ParameterError, shorten } from '../physics/validate.ts';
import { CASE_FIELDS, type CaseField, type ColorCase, type RawCase, isValidId, validateColorCase } from './colorCase.ts';
import { describePath, describeValue, rejectValue } from './inputErrors.ts';
import { jsonNestingDepth } from './jsonNestingDepth.ts';

/** More cases than this in one file is a mistake, not a workload. */
export const MAX_CASES = 100_000;

/**
 * The deepest nesting a cases file may have. A valid one needs 3 levels (the array, a case, its
 * `illuminant` object or `wavelengthsNm` array); the rest is room for a file a later version
 * writes, and far below what would exhaust the parser's or the printer's stack.
 */
export const MAX_CASES_NESTING_DEPTH = 16;

const CASE_EXPECTED = `an object with some of the fields ${CASE_FIELDS.join(', ')}`;

/**
 * The cases of a `--cases` file: a JSON array of objects with the fields of `CASE_FIELDS`, each
 * optional (see `validateColorCase` for the defaults). Every case is checked before any is
 * computed; the first bad one throws a ParameterError that names the case and the field. A text
 * nested deeper than MAX_CASES_NESTING_DEPTH is refused before it is parsed.
 * `fileName` is only for messages.
 */
export function parseCasesJson(text: string, fileName: string): ColorCase[] {
  const depth = jsonNestingDepth(text);
  if (depth > MAX_CASES_NESTING_DEPTH) {
    const message =
      `--cases: ${describePath(fileName)} is malformed: its arrays and objects nest ${depth} deep; ` +
      `expected at most ${MAX_CASES_NESTING_DEPTH} levels (a JSON array of cases)`;
    throw new ParameterError('--cases', message);
  }
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (error) {
    const reason = shorten(error instanceof Error ? error.message : String(error), 80);
    const message = `--cases: ${describePath(fileName)} is not valid JSON (${reason}); expected a JSON array of cases`;
    throw new ParameterError('--cases', message);
  }
  if (!Array.isArray(data)) return rejectValue('--cases', data, 'a JSON array of cases');
  if (data.length > MAX_CASES) {
    throw new ParameterError('--cases', `--cases: ${data.length} cases is not allowed; expected at most ${MAX_CASES}`);
  }
  return data.map((entry: unknown, index) => parseCase(entry, index));
}

function parseCase(entry: unknown, index: number): ColorCase {
  const isObject = typeof entry === 'object' && entry !== null && !Array.isArray(entry);
  const id = isObject ? (entry as RawCase).id : undefined;
  const label = isValidId(id) ? `case ${describeValue(id)} (index ${index})` : `case at index ${index}`;
  try {
    if (!isObject) return rejectValue('case', entry, CASE_EXPECTED);
    const raw: Partial<Record<CaseField, unknown>> = {};
    for (const [key, value] of Object.entries(entry)) {
      if (!(CASE_FIELDS as readonly string[]).includes(key)) {
        throw new ParameterError(key, `${describeValue(key)}: unknown field; expected one of ${CASE_FIELDS.join(', ')}`);
      }
      raw[key as CaseField] = value;
    }
    return validateColorCase(raw, index);
  } catch (error) {
    if (!(error instanceof ParameterError)) throw error;
    throw new ParameterError(error.parameter, `${label}: ${error.message}`);
  }
}

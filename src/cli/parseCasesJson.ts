import { describeValue, ParameterError, rejectValue } from '../input/validate.ts';
import { CASE_FIELDS, type CaseField, type ColorCase, type RawCase, isValidId, validateColorCase } from './colorCase.ts';
import { parseJsonArray } from './parseJsonArray.ts';

const CASE_EXPECTED = `an object with some of the fields ${CASE_FIELDS.join(', ')}`;

/**
 * The cases of a `--cases` file: a JSON array of objects with the fields of `CASE_FIELDS`, each
 * optional (see `validateColorCase` for the defaults), read by `parseJsonArray`. Every case is
 * checked before any is computed; the first bad one throws a ParameterError that names the case
 * and the field. `fileName` is only for messages.
 */
export function parseCasesJson(text: string, fileName: string): ColorCase[] {
  return parseJsonArray(text, fileName, 'cases').map((entry: unknown, index) => parseCase(entry, index));
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

/**
 * The TypeScript ↔ GLSL contract for a choice among names: the define `NAME` holds the chosen
 * value's code and `NAME_VALUE` each value's, so a shader compares by name
 * (`#if TFC_FILM_MODE == TFC_FILM_MODE_TABLE`), never by a number. The codes come from the list's
 * order, but both sides take them from here: reordering the list cannot change what is drawn.
 */

/** `display-p3` → `DISPLAY_P3`, `three-iridescence` → `THREE_IRIDESCENCE`. */
const constantName = (name: string, value: string): string => `${name}_${value.toUpperCase().replace(/[^A-Z0-9]+/g, '_')}`;

/** `NAME_VALUE` = code for every value, without a selection (for a shader that takes the choice as a uniform). */
export function enumConstants(name: string, values: readonly string[]): Record<string, number> {
  return Object.fromEntries(values.map((v, code) => [constantName(name, v), code]));
}

/** The code of `value`, for a uniform compared with enumConstants' names. */
export function enumCode<T extends string>(name: string, values: readonly T[], value: T): number {
  const code = values.indexOf(value);
  if (code < 0) throw new Error(`${name}: ${JSON.stringify(value)} is not one of ${values.join(', ')}`);
  return code;
}

/** The constants and `NAME` = the code of `value`. */
export function enumDefines<T extends string>(name: string, values: readonly T[], value: T): Record<string, number> {
  return { ...enumConstants(name, values), [name]: enumCode(name, values, value) };
}

/**
 * GLSL holding each value's source under its named `#if` (`#if NAME == NAME_VALUE`), so a program
 * keeps the one that the define `NAME` selects.
 */
export function enumSource<T extends string>(name: string, values: readonly T[], sourceOf: (value: T) => string): string {
  const constants = Object.keys(enumConstants(name, values));
  return `${values.map((v, i) => `${i === 0 ? '#if' : '#elif'} ${name} == ${constants[i]}\n${sourceOf(v)}`).join('\n')}\n#endif\n`;
}

import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS, type ViewSettings } from './viewParameters.ts';
import { quoted } from '../input/validate.ts';
import { type ParameterRow, expectationText } from './parameterRow.ts';
import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';

/** Longer values are refused outright (a mangled link, not a number), unless a row says it takes more (`maxLength`). */
export const MAX_VALUE_LENGTH = 64;

/** The longest value a row reads. */
const maxLengthOf = (row: ParameterRow<ViewSettings>): number => row.maxLength ?? MAX_VALUE_LENGTH;

/** The schema's rows by URL name (own keys only: `?constructor=` must not reach Object.prototype). */
const BY_URL = new Map(VIEW_PARAMETERS.map((row) => [row.url, row]));

/** The schema's row of the parameter named `name` in the URL (and in the render command), if any. */
export const parameterNamed = (name: string): ParameterRow<ViewSettings> | undefined => BY_URL.get(name);

/**
 * One parameter's reading of a raw value, as the URL reads it: its settings, or the refusal (what
 * it expects). A value longer than the row's maximum (MAX_VALUE_LENGTH unless it says) is refused outright.
 */
export function readParameter(
  row: ParameterRow<ViewSettings>,
  raw: string,
): { readonly read: Partial<ViewSettings> } | { readonly expected: string } {
  if (raw.length > maxLengthOf(row)) return { expected: `${row.expected} of at most ${maxLengthOf(row)} characters` };
  const read = row.read(raw);
  if (read) return { read };
  const problem = row.problem?.(raw);
  return { expected: problem ? `${row.expected} (here ${problem})` : row.expected };
}

/** A refused value: the parameter's row, the value as given, and what was wrong beyond the row's range (if the row says). */
export interface Refusal {
  readonly row: ParameterRow<ViewSettings>;
  readonly raw: string;
  readonly tooLong: boolean;
  readonly problem: string | null;
}

/**
 * A refusal as one line in a catalogue's language, naming the parameter, the value (quoted, cut
 * short) and what it accepts. The row's own detail on what was wrong is English (src/physics), so
 * a catalogue without `{problem}` in `refusal.ignoredProblem` leaves it out.
 */
export function refusalText(r: Refusal, cat: Catalogue = EN): string {
  const accepts = expectationText(r.row.expects, cat);
  const expected = r.tooLong ? message(cat, 'expected.tooLong', { expected: accepts, max: maxLengthOf(r.row) }) : accepts;
  const values = { name: r.row.url, value: quoted(r.raw), expected, problem: r.problem ?? '' };
  return message(cat, r.problem ? 'refusal.ignoredProblem' : 'refusal.ignored', values);
}

/** The refusal of `raw` by `row`, or null when the row reads it. */
function refusalOf(row: ParameterRow<ViewSettings>, raw: string): Refusal | null {
  if (raw.length > maxLengthOf(row)) return { row, raw, tooLong: true, problem: null };
  return row.read(raw) ? null : { row, raw, tooLong: false, problem: row.problem?.(raw) ?? null };
}

export interface ParsedSettings {
  readonly settings: ViewSettings;
  /** One line per refused parameter, naming it and its allowed range; its default was kept. */
  readonly errors: readonly string[];
  /** The same refusals, for a message in another language (refusalText). */
  readonly refusals: readonly Refusal[];
}

/**
 * Reads settings from a query string. A bad value is reported and never used: the setting keeps
 * its value from `base`, or from an earlier good occurrence of the same parameter. Unknown names
 * belong to others (the embedding page) and are skipped.
 */
export function parseSettings(query: string, base: ViewSettings = DEFAULT_VIEW_SETTINGS): ParsedSettings {
  let settings = base;
  const refusals: Refusal[] = [];
  for (const [name, raw] of new URLSearchParams(query)) {
    const row = parameterNamed(name);
    if (!row) continue;
    const refusal = refusalOf(row, raw);
    if (refusal) refusals.push(refusal);
    else settings = { ...settings, ...row.read(raw) };
  }
  return { settings, errors: refusals.map((r) => refusalText(r)), refusals };
}

/**
 * The query string that `parseSettings` with the same `base` turns back into these settings: what
 * equals `base` (a page's default view) is left out.
 */
export function settingsToQuery(s: ViewSettings, base: ViewSettings = DEFAULT_VIEW_SETTINGS): string {
  const pairs = VIEW_PARAMETERS.map((row) => [row.url, row.write(s), row.write(base)] as const);
  return new URLSearchParams(pairs.filter(([, v, d]) => v !== d).map(([k, v]) => [k, v])).toString();
}

import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS, type ViewSettings } from './viewParameters.ts';
import { quoted } from '../physics/validate.ts';
import type { ParameterRow } from './parameterRow.ts';

/** Longer values are refused outright (a mangled link, not a number). */
export const MAX_VALUE_LENGTH = 64;

/** The schema's rows by URL name (own keys only: `?constructor=` must not reach Object.prototype). */
const BY_URL = new Map(VIEW_PARAMETERS.map((row) => [row.url, row]));

/** The schema's row of the parameter named `name` in the URL (and in the render command), if any. */
export const parameterNamed = (name: string): ParameterRow<ViewSettings> | undefined => BY_URL.get(name);

/**
 * One parameter's reading of a raw value, as the URL reads it: its settings, or the refusal (what
 * it expects). A value longer than MAX_VALUE_LENGTH is refused outright.
 */
export function readParameter(
  row: ParameterRow<ViewSettings>,
  raw: string,
): { readonly read: Partial<ViewSettings> } | { readonly expected: string } {
  if (raw.length > MAX_VALUE_LENGTH) return { expected: `${row.expected} of at most ${MAX_VALUE_LENGTH} characters` };
  const read = row.read(raw);
  if (read) return { read };
  const problem = row.problem?.(raw);
  return { expected: problem ? `${row.expected} (here ${problem})` : row.expected };
}

export interface ParsedSettings {
  readonly settings: ViewSettings;
  /** One line per refused parameter, naming it and its allowed range; its default was kept. */
  readonly errors: readonly string[];
}

/**
 * Reads settings from a query string. A bad value is reported and never used: the setting keeps
 * its value from `base`, or from an earlier good occurrence of the same parameter. Unknown names
 * belong to others (the embedding page) and are skipped.
 */
export function parseSettings(query: string, base: ViewSettings = DEFAULT_VIEW_SETTINGS): ParsedSettings {
  let settings = base;
  const errors: string[] = [];
  for (const [name, raw] of new URLSearchParams(query)) {
    const row = parameterNamed(name);
    if (!row) continue;
    const reading = readParameter(row, raw);
    if ('read' in reading) settings = { ...settings, ...reading.read };
    else errors.push(`${name}=${quoted(raw)} ignored: expected ${reading.expected}`);
  }
  return { settings, errors };
}

/** The query string that `parseSettings` turns back into these settings (defaults left out). */
export function settingsToQuery(s: ViewSettings): string {
  const pairs = VIEW_PARAMETERS.map((row) => [row.url, row.write(s), row.defaultText] as const);
  return new URLSearchParams(pairs.filter(([, v, d]) => v !== d).map(([k, v]) => [k, v])).toString();
}

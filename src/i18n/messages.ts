import { type Catalogue, EN, type MessageKey } from './en.ts';
import { JA } from './ja.ts';

/** The languages with a catalogue, by their BCP 47 primary subtag. */
const CATALOGUES: Readonly<Record<string, Catalogue>> = { en: EN, ja: JA };

/** The languages a page can be shown in (`lang=` in the demo's URL). */
export const LANGUAGES: readonly string[] = Object.keys(CATALOGUES);

/** The catalogue for a `lang` value (`ja`, `ja-JP`, …); English for any language without one. */
export function catalogueFor(lang: string): Catalogue {
  const primary = lang.trim().toLowerCase().split('-')[0] ?? '';
  return Object.hasOwn(CATALOGUES, primary) ? CATALOGUES[primary]! : EN;
}

/** The primary subtag `catalogueFor` chose ('en' for a language without a catalogue), for the `lang` attribute. */
export const catalogueLang = (lang: string): string => (catalogueFor(lang) === JA ? 'ja' : 'en');

/** A text with its `{name}` marks filled in from `values` (a mark without a value stays as it is). */
export function message(catalogue: Catalogue, key: MessageKey, values: Readonly<Record<string, string | number>> = {}): string {
  return catalogue[key].replace(/\{(\w+)\}/g, (mark, name: string) => (Object.hasOwn(values, name) ? String(values[name]) : mark));
}

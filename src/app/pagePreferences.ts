import { type Catalogue, EN } from '../i18n/en.ts';
import { LANGUAGES, catalogueFor, catalogueLang, message } from '../i18n/messages.ts';
import { quoted } from '../input/validate.ts';

/** Whether the user asks for less motion (the media query), so the swirl starts still unless asked to move. */
export const prefersReducedMotion = (win: Window = window): boolean =>
  win.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false;

/** The page's language from its URL (`lang`, one of LANGUAGES) or else its `<html lang>`, and a refusal of a bad `lang` in English. */
export function pageLanguage(query: URLSearchParams, htmlLang: string): { lang: string; cat: Catalogue; error: string | null } {
  const asked = query.get('lang');
  if (asked === null || LANGUAGES.includes(asked)) {
    const lang = catalogueLang(asked ?? htmlLang);
    return { lang, cat: catalogueFor(lang), error: null };
  }
  const expected = message(EN, 'expected.choice', { choices: LANGUAGES.join(', ') });
  return { lang: 'en', cat: EN, error: message(EN, 'refusal.ignored', { name: 'lang', value: quoted(asked), expected }) };
}

import { drawnMethod } from '../methods/methods.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';

/**
 * The settings the app draws, and the line saying why they differ from those asked for (null when
 * they do not): where the method asked for does not support the film's fill, the registry names the
 * one drawn instead (`drawnMethod`, src/methods/filmFills.ts). The asked-for mode stays in the settings (URL,
 * panel); only the view is given the other.
 */
export function shownMethod(s: FilmSettings, cat: Catalogue = EN): { readonly settings: FilmSettings; readonly notice: string | null } {
  const { mode, instead } = drawnMethod(s);
  if (!instead) return { settings: s, notice: null };
  return { settings: { ...s, mode }, notice: message(cat, instead.notice, instead.values) };
}

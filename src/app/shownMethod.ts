import { isDispersiveMedium, mediumText } from '../physics/medium.ts';
import { isDispersiveFilm } from '../film/filmMedia.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';

/**
 * The settings the app draws, and the line saying why they differ from those asked for (null when
 * they do not). `fourier` has no Airy series for a dispersive film or inside (docs/physics.md#a-dispersive-film):
 * its shader sums the dispersive bins per fragment, hundreds of times the cost of a plain textured
 * sphere on a software rasteriser; the table is filled from the same bins, once per change rather
 * than once per pixel per frame, so the app draws the table instead and says so. The asked-for
 * mode stays in the settings (URL, panel); only the view is given the table.
 */
export function shownMethod(s: FilmSettings, cat: Catalogue = EN): { readonly settings: FilmSettings; readonly notice: string | null } {
  if (s.mode !== 'fourier' || !isDispersiveFilm(s)) return { settings: s, notice: null };
  return {
    settings: { ...s, mode: 'table' },
    notice: message(
      cat,
      'app.fourierAsTable',
      isDispersiveMedium(s.nFilm) ? { name: 'nFilm', medium: mediumText(s.nFilm) } : { name: 'nInside', medium: mediumText(s.nInside) },
    ),
  };
}

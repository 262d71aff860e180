import type { MessageKey } from '../i18n/en.ts';
import type { FilmMethodSettings } from '../methods/filmMethod.ts';
import { type FilmMethodName, drawnMethod, methodReads } from '../methods/methods.ts';
import { SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantLines, illuminantText } from '../physics/illuminantSpec.ts';

/** A line saying why something is drawn in place of what was asked: a message of the catalogues and its `{marks}`. */
export interface DrawnNotice {
  readonly key: MessageKey;
  readonly values: Readonly<Record<string, string | number>>;
}

/**
 * Who draws the film. The demo's view (`view`) holds a frame rate: where the method asked for would
 * cost hundreds of times its usual fragment (`fourier`'s bins for a dispersive film or inside), the
 * method the registry names in its place draws the film. A material (`material`) draws the method its
 * user chose for the one film, whatever it costs; only a film the method has no form for (a stack of
 * films in `fourier`) is drawn by another.
 */
export type FilmDrawer = 'view' | 'material';

/** The media a method's form does not depend on: what a material's film is asked with (its dispersion left to the method). */
const PLAIN_MEDIA = { nFilm: SOAP_FILM_IN_AIR.nFilm, nInside: SOAP_FILM_IN_AIR.nInside } as const;

/**
 * The method that draws a film under a line source in the place of one that reads the table. A
 * line source's colour is a sum over its few lines, R at one wavelength each: `exact` sums them per
 * fragment at any thickness, while under a line the fringes never wash out with thickness and a
 * table's grid, spaced for light whose fringes do, cannot hold them (docs/physics.md#lights).
 */
const LINES_METHOD: FilmMethodName = 'exact';

/**
 * The film-level part of what is drawn for what is asked (the app's whole frame: src/app/drawnFrame.ts):
 * the method that draws the film `s`, the one asked for or the one its registry entry names in its
 * place (`drawnInstead`, src/methods/), or `exact` for a table under a line source, and the notice
 * saying why (null when it is the one asked for). The film keeps everything else as asked.
 */
export function drawnFilmMethod<S extends FilmMethodSettings & { readonly mode: FilmMethodName; readonly illuminant: IlluminantSpec }>(
  s: S,
  drawer: FilmDrawer,
): { readonly film: S; readonly notice: DrawnNotice | null } {
  const { mode, instead } = drawnMethod(drawer === 'view' ? s : { ...s, ...PLAIN_MEDIA });
  if (methodReads(mode, 'table') && illuminantLines(s.illuminant) !== null) {
    return {
      film: { ...s, mode: LINES_METHOD },
      notice: { key: 'app.linesAsExact', values: { method: s.mode, light: illuminantText(s.illuminant), drawn: LINES_METHOD } },
    };
  }
  if (!instead) return { film: s, notice: null };
  return { film: { ...s, mode }, notice: { key: instead.notice, values: instead.values } };
}

import type { FilmLayer } from '../physics/stackFilms.ts';
import { type Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { ParameterRow } from '../settings/parameterRow.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';

/**
 * The panel's text field of a stack of films read as the URL reads it (the schema's row): the films
 * it writes, or, where it writes none, the last good stack `last` kept and a title saying why the
 * text is not taken (as the Cauchy and complex fields say it). The empty text is the empty stack:
 * the single film.
 */
export function readStackField(
  row: ParameterRow<ViewSettings>,
  text: string,
  last: readonly FilmLayer[],
  cat: Catalogue,
): { readonly films: readonly FilmLayer[]; readonly title: string } {
  const films = row.read(text)?.[row.key] as readonly FilmLayer[] | undefined;
  if (films) return { films, title: '' };
  const problem = row.problem?.(text) ?? row.expected;
  return { films: last, title: message(cat, 'panel.notTaken', { problem }) };
}

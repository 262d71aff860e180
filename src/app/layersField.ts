import type { FilmLayer } from '../physics/filmLayers.ts';
import { type Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { ParameterRow } from '../settings/parameterRow.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';

/**
 * The panel's layers text field read as the URL reads it (the schema's row): the stack it writes,
 * or, where it writes none, the last good stack `last` kept and a title saying why the text is not
 * taken (as the Cauchy and complex fields say it). The empty text is the empty stack: the single film.
 */
export function readLayersField(
  row: ParameterRow<ViewSettings>,
  text: string,
  last: readonly FilmLayer[],
  cat: Catalogue,
): { readonly layers: readonly FilmLayer[]; readonly title: string } {
  const reading = row.read(text);
  if (reading?.layers) return { layers: reading.layers, title: '' };
  const problem = row.problem?.(text) ?? row.expected;
  return { layers: last, title: message(cat, 'panel.notTaken', { problem }) };
}

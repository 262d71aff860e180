import { cAbs2 } from '../physics/complex.ts';
import type { FilmBeams } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { fourFigures } from './numberText.ts';
import { beamFormula, beamName, formulaNodes } from './svgNodes.ts';

/**
 * The beams as a table: each E_n's amplitude as a formula (eqs 3, 7, 13) and its magnitude in each
 * channel, then the bound on the tail left out and |E| of the whole sum.
 */
export function fillBeamTable(
  table: HTMLTableElement,
  beams: FilmBeams,
  channelNames: readonly string[],
  flipTop: boolean,
  cat: Catalogue,
): void {
  const doc = table.ownerDocument;
  const cell = (tag: 'td' | 'th', content: string | Node[]) => {
    const c = doc.createElement(tag);
    if (typeof content === 'string') c.textContent = content;
    else c.append(...content);
    if (tag === 'th') c.setAttribute('scope', 'col');
    return c;
  };
  const row = (cells: HTMLTableCellElement[]) => {
    const r = doc.createElement('tr');
    r.append(...cells);
    return r;
  };
  const caption = Object.assign(doc.createElement('caption'), { textContent: cat['diagram.beamsCaption'] });
  const head = doc.createElement('thead');
  head.append(
    row([
      cell('th', cat['diagram.beam']),
      cell('th', cat['diagram.amplitude']),
      ...channelNames.map((channel) =>
        cell('th', formulaNodes(doc, message(cat, 'diagram.magnitude', { channel }).replace('E_n', 'E_{n}'), false)),
      ),
    ]),
  );
  const body = doc.createElement('tbody');
  const count = Math.max(...beams.channels.map((c) => c.beams.beams.length));
  for (let n = 0; n < count; n++) {
    const magnitudes = beams.channels.map((c) => {
      const e = c.beams.beams[n];
      return cell('td', e ? fourFigures(Math.sqrt(cAbs2(e))) : '—');
    });
    body.append(
      row([
        cell('td', formulaNodes(doc, beamName(n), false)),
        cell('td', formulaNodes(doc, beamFormula(n, flipTop), false)),
        ...magnitudes,
      ]),
    );
  }
  body.append(
    row([
      cell('td', cat['diagram.tail']),
      cell('td', '≤'),
      ...beams.channels.map((c) => cell('td', Number.isFinite(c.beams.tailBound) ? fourFigures(c.beams.tailBound) : '∞')),
    ]),
    row([
      cell('td', 'E'),
      cell('td', cat['diagram.total']),
      ...beams.channels.map((c) => cell('td', fourFigures(Math.sqrt(cAbs2(c.beams.total))))),
    ]),
  );
  table.replaceChildren(caption, head, body);
}

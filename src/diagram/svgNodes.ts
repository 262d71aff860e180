/** Small builders for the diagram's SVG and its formulas; text goes in as text nodes only, never as markup. */

export const SVG_NS = 'http://www.w3.org/2000/svg';

/** An SVG element with its attributes (numbers rounded to 0.01 of a unit) and, optionally, its text. */
export function svg<K extends keyof SVGElementTagNameMap>(
  doc: Document,
  tag: K,
  attributes: Readonly<Record<string, string | number>> = {},
  text?: string,
): SVGElementTagNameMap[K] {
  const el = doc.createElementNS(SVG_NS, tag);
  for (const [name, value] of Object.entries(attributes))
    el.setAttribute(name, typeof value === 'number' ? String(+value.toFixed(2)) : value);
  if (text !== undefined) el.textContent = text;
  return el;
}

/** Appends an SVG element (as `svg` makes it) to `parent`: how the figures draw, element by element. */
export function appendSvg<K extends keyof SVGElementTagNameMap>(
  parent: Element,
  tag: K,
  attributes: Readonly<Record<string, string | number>> = {},
  text?: string,
): SVGElementTagNameMap[K] {
  return parent.appendChild(svg(parent.ownerDocument, tag, attributes, text));
}

/** Empties a figure for drawing anew in a box of `width` × `height` SVG units, which scales to any width (viewBox). */
export function clearFigure(figure: SVGSVGElement, width: number, height: number): void {
  figure.replaceChildren();
  figure.setAttribute('viewBox', `0 0 ${width} ${height}`);
}

/** A figure's title and description (its accessible name and text, referred to by `ids`). */
export function describeFigure(
  figure: SVGSVGElement,
  ids: { readonly title: string; readonly desc: string },
  title: string,
  desc: string,
): void {
  appendSvg(figure, 'title', { id: ids.title }, title);
  appendSvg(figure, 'desc', { id: ids.desc }, desc);
}

/**
 * A formula written with `_{…}` for subscripts and `^{…}` for superscripts (`t_{ab} e^{2iφ}`), as
 * nodes: HTML <sub>/<sup>, or SVG <tspan>s shifted by `baseline-shift`.
 */
export function formulaNodes(doc: Document, formula: string, inSvg: boolean): Node[] {
  const nodes: Node[] = [];
  const pattern = /([_^])\{([^}]*)\}/g;
  let at = 0;
  for (const match of formula.matchAll(pattern)) {
    if (match.index > at) nodes.push(doc.createTextNode(formula.slice(at, match.index)));
    const sub = match[1] === '_';
    const text = match[2]!;
    nodes.push(
      inSvg
        ? svg(doc, 'tspan', { 'baseline-shift': sub ? 'sub' : 'super', 'font-size': '70%' }, text)
        : Object.assign(doc.createElement(sub ? 'sub' : 'sup'), { textContent: text }),
    );
    at = match.index + match[0].length;
  }
  if (at < formula.length) nodes.push(doc.createTextNode(formula.slice(at)));
  return nodes;
}

/** The formula of beam E_n (eqs 3, 7, 13), E_0's sign reversed when the top surface has no phase flip. */
export function beamFormula(n: number, flipTop: boolean): string {
  if (n === 0) return flipTop ? '−r_{ab}' : 'r_{ab}';
  const phase = n === 1 ? 'e^{iφ}' : `e^{${n}iφ}`;
  const trips = n === 1 ? '' : n === 2 ? ' (r_{ba} r_{bc})' : ` (r_{ba} r_{bc})^{${n - 1}}`;
  return `t_{ab} t_{ba} r_{bc}${trips} ${phase}`;
}

/** E_n's name with its index as a subscript. */
export const beamName = (n: number): string => `E_{${n}}`;

/** A formula as plain text (for titles and descriptions): the marks dropped. */
export const plainFormula = (formula: string): string => formula.replace(/_\{([^}]*)\}/g, '_$1').replace(/\^\{([^}]*)\}/g, '^$1');

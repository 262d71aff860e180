import type { ChartLayout } from './chartLayout.ts';

/**
 * A chart as SVG: the same layout as the PNG, one `rect` per cell (per row of the table) filled
 * with its hex colour, ticks as `line`s and labels as `text`. Every text written is a number or
 * a unit, so nothing needs escaping.
 */
export function chartSvg(layout: ChartLayout): string {
  const { width, height } = layout;
  const rects = layout.cells.map((c) => `<rect x="${c.x}" y="${c.y}" width="${c.width}" height="${c.height}" fill="${c.hex}"/>`);
  const lines = layout.ticks.map((t) => `<line x1="${t.x1 + 0.5}" y1="${t.y1}" x2="${t.x2 + 0.5}" y2="${t.y2}"/>`);
  const texts = layout.labels.map((l) => `<text x="${l.x}" y="${l.y + 7}" text-anchor="${l.anchor}">${l.text}</text>`);
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" shape-rendering="crispEdges" style="background:#fff">`,
    ...rects,
    `<g stroke="#000" stroke-width="1">${lines.join('')}</g>`,
    `<g font-family="sans-serif" font-size="8" fill="#000">${texts.join('')}</g>`,
    '</svg>',
    '',
  ].join('\n');
}

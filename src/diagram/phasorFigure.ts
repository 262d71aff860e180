import { type Complex, cAbs2, cAdd } from '../physics/complex.ts';
import type { ChannelBeams, ReflectedBeams } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { complexText, fourFigures } from './numberText.ts';
import { appendSvg, clearFigure, describeFigure, svg } from './svgNodes.ts';

const SIZE = 200;
const MARGIN = 22;
/** Arrows shorter than this (SVG units) are drawn without a head, which would hide them. */
const MIN_HEAD_LENGTH = 4;
/** The beams' colours in turn, all dark enough for text contrast on white. */
const COLORS = ['#b03a00', '#1f4fbf', '#2f6b1f', '#7a2a8c', '#8a5a00', '#005f73'];

/** The complex plane's axes, and (in their defs) the arrowhead the phasors end in. */
function drawAxes(figure: SVGSVGElement, markerId: string): void {
  const defs = appendSvg(figure, 'defs');
  const marker = appendSvg(defs, 'marker', {
    id: markerId,
    viewBox: '0 0 10 10',
    refX: 9,
    refY: 5,
    markerWidth: 5,
    markerHeight: 5,
    orient: 'auto-start-reverse',
  });
  appendSvg(marker, 'path', { d: 'M 0 0 L 10 5 L 0 10 z', fill: '#1b1b1b' });
  appendSvg(figure, 'line', { x1: 4, y1: SIZE / 2, x2: SIZE - 4, y2: SIZE / 2, stroke: '#777', 'stroke-width': 0.6 });
  appendSvg(figure, 'line', { x1: SIZE / 2, y1: SIZE - 14, x2: SIZE / 2, y2: 4, stroke: '#777', 'stroke-width': 0.6 });
  appendSvg(figure, 'text', { x: SIZE - 4, y: SIZE / 2 - 3, 'font-size': 8, 'text-anchor': 'end', fill: '#1b1b1b' }, 'Re');
  appendSvg(figure, 'text', { x: SIZE / 2 + 3, y: 10, 'font-size': 8, fill: '#1b1b1b' }, 'Im');
}

/** The phasors' heads, E_0, E_1, … added head to tail from the origin, and the plane drawn to fit them and the resultant. */
interface PhasorPlane {
  readonly heads: readonly Complex[];
  /** SVG units per unit of amplitude */
  readonly scale: number;
  /** a point of the complex plane in the figure */
  readonly at: (p: Complex) => readonly [number, number];
}

function phasorPlane({ beams, total }: ReflectedBeams): PhasorPlane {
  const heads: Complex[] = [{ re: 0, im: 0 }];
  for (const e of beams) heads.push(cAdd(heads[heads.length - 1]!, e));
  const all = [...heads, total];
  const extent = Math.max(1e-12, ...all.map((p) => Math.max(Math.abs(p.re), Math.abs(p.im))));
  const scale = (SIZE / 2 - MARGIN) / extent;
  return { heads, scale, at: (p) => [SIZE / 2 + p.re * scale, SIZE / 2 - p.im * scale] };
}

/** An arrow from `from` to `to`, headed (marker `markerId`) where it is long enough to show the head. */
function drawArrow(
  figure: SVGSVGElement,
  at: PhasorPlane['at'],
  markerId: string,
  from: Complex,
  to: Complex,
  attrs: Record<string, string | number>,
) {
  const [x1, y1] = at(from);
  const [x2, y2] = at(to);
  const head: Record<string, string> = Math.hypot(x2 - x1, y2 - y1) >= MIN_HEAD_LENGTH ? { 'marker-end': `url(#${markerId})` } : {};
  return appendSvg(figure, 'line', { x1, y1, x2, y2, 'stroke-linecap': 'round', ...head, ...attrs });
}

/**
 * One channel's phasor diagram (eq 13 in the complex plane): E_0, E_1, … head to tail from the
 * origin, the closed-form tail where beams were left out, and the resultant E, with |E|² = R.
 */
export function drawPhasorFigure(
  figure: SVGSVGElement,
  channel: ChannelBeams,
  channelName: string,
  catalogue: Catalogue,
  ids: { title: string; desc: string; marker: string },
): void {
  clearFigure(figure, SIZE, SIZE);
  const { beams, total } = channel.beams;
  const reflectance = cAbs2(total);
  const description = message(catalogue, 'diagram.phasorDescription', { total: complexText(total), reflectance: fourFigures(reflectance) });
  describeFigure(figure, ids, message(catalogue, 'diagram.phasorTitle', { channel: channelName }), description);
  drawAxes(figure, ids.marker);
  const { heads, scale, at } = phasorPlane(channel.beams);
  const arrow = (from: Complex, to: Complex, attrs: Record<string, string | number>) => drawArrow(figure, at, ids.marker, from, to, attrs);
  beams.forEach((e, n) => {
    const line = arrow(heads[n]!, heads[n + 1]!, { stroke: COLORS[n % COLORS.length]!, 'stroke-width': 1.6, 'data-beam': n });
    line.appendChild(svg(figure.ownerDocument, 'title', {}, `E${n} = ${complexText(e)}`));
    if (n < 3) {
      const [x, y] = at({ re: (heads[n]!.re + heads[n + 1]!.re) / 2, im: (heads[n]!.im + heads[n + 1]!.im) / 2 });
      appendSvg(figure, 'text', { x: x + 3, y: y - 3, 'font-size': 8, fill: COLORS[n % COLORS.length]! }, `E${n}`);
    }
  });
  const reached = heads[heads.length - 1]!;
  const leftOut = Math.sqrt(cAbs2({ re: total.re - reached.re, im: total.im - reached.im }));
  if (leftOut * scale >= 1) arrow(reached, total, { stroke: '#555', 'stroke-width': 1, 'stroke-dasharray': '1.5 1.5' });
  arrow({ re: 0, im: 0 }, total, { stroke: '#1b1b1b', 'stroke-width': 1.2, 'stroke-dasharray': '4 2', 'data-total': '' });
  const [ex, ey] = at(total);
  appendSvg(figure, 'text', { x: ex + 4, y: ey + 10, 'font-size': 9, 'font-weight': 'bold', fill: '#1b1b1b' }, 'E');
  appendSvg(figure, 'text', { x: 4, y: SIZE - 15, 'font-size': 8, fill: '#1b1b1b' }, channelName);
  appendSvg(figure, 'text', { x: 4, y: SIZE - 4, 'font-size': 9, fill: '#1b1b1b' }, `|E|² = R = ${fourFigures(reflectance)}`);
}

import { cAbs2 } from '../physics/complex.ts';
import type { FilmStack } from '../physics/filmReflectance.ts';
import { type FilmBeams, filmAngles, opticalPathNm } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { complexText, fourFigures, settingText } from './numberText.ts';
import { beamFormula, beamName, formulaNodes, plainFormula, svg } from './svgNodes.ts';

/** The figure's box in SVG units; it scales to any width (viewBox), so it stays crisp. */
const WIDTH = 400;
const HEIGHT = 250;
/** Where the film's top surface is drawn, and where the incident ray meets it. */
const SURFACE_Y = 105;
const X0 = 110;
/** The film is drawn this thick (SVG units) at most, thinner where many beams must fit; its real d is in its label. */
const MAX_FILM = 50;
const MIN_FILM = 12;
const RAY = 95;
/** Angles outside this range are drawn at its ends, so the beams stay apart and on the page (the labels say so). */
const DRAWN_DEG = { min: 12, max: 78 } as const;
/** A nominal angle for the path in an evanescent film, which has no real θ_ri. */
const EVANESCENT_DRAWN_DEG = 50;
/** The widest beam (the strongest); every other is as wide in proportion to |E_n|, with a hairline at least. */
const MAX_BEAM_WIDTH = 7;
const HAIRLINE = 0.5;
/** Beams labelled with their whole amplitude; later ones carry their names only (the table has all). */
const FORMULA_LABELS = 3;
const DEG = Math.PI / 180;

export interface BeamFigureInput {
  readonly stack: FilmStack;
  readonly beams: FilmBeams;
  readonly flipTop: boolean;
  readonly catalogue: Catalogue;
}

/** |E_n| averaged over the channels in intensity (√ of the mean |E_n|²), for n = 0 … N. */
export function beamMagnitudes(beams: FilmBeams): number[] {
  const count = Math.max(...beams.channels.map((c) => c.beams.beams.length));
  return Array.from({ length: count }, (_, n) => {
    const sum = beams.channels.reduce((s, c) => s + cAbs2(c.beams.beams[n] ?? { re: 0, im: 0 }), 0);
    return Math.sqrt(sum / beams.channels.length);
  });
}

/**
 * The paper's Figure 1, live: media a | b | c with their indices, the incident ray at θ_i, the
 * path refracted at θ_ri (eq 1) through the film, the reflected beams E_0 … E_N (eqs 3, 7, 13),
 * each as wide as |E_n|, and the optical path difference Δ (eq 12) between E_0 and E_1.
 */
export function drawBeamFigure(figure: SVGSVGElement, input: BeamFigureInput, ids: { title: string; desc: string }): void {
  const doc = figure.ownerDocument;
  const { stack, beams, flipTop, catalogue: cat } = input;
  const el = <K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number> = {}, text?: string) =>
    figure.appendChild(svg(doc, tag, attrs, text));
  figure.replaceChildren();
  figure.setAttribute('viewBox', `0 0 ${WIDTH} ${HEIGHT}`);

  const { cosRefracted, cosTransmitted } = filmAngles(stack);
  const evanescent = cosRefracted.im !== 0;
  const magnitudes = beamMagnitudes(beams);
  const last = magnitudes.length - 1;
  const drawnDeg = Math.min(DRAWN_DEG.max, Math.max(DRAWN_DEG.min, stack.angleDeg));
  const sinI = Math.sin(drawnDeg * DEG),
    cosI = Math.cos(drawnDeg * DEG);
  const sinR = evanescent ? Math.sin(EVANESCENT_DRAWN_DEG * DEG) : Math.min(0.95, (stack.nOutside * sinI) / stack.nFilm);
  const tanR = sinR / Math.sqrt(1 - sinR * sinR);
  const film = last > 0 ? Math.min(MAX_FILM, Math.max(MIN_FILM, (WIDTH - X0 - 70) / (2 * last * tanR))) : MAX_FILM;
  const step = 2 * film * tanR;
  const back = SURFACE_Y + film;

  const refracted = evanescent ? cat['diagram.evanescent'] : `${(Math.acos(cosRefracted.re) / DEG).toFixed(1)}°`;
  el('title', { id: ids.title }, cat['diagram.figureTitle']);
  el(
    'desc',
    { id: ids.desc },
    message(cat, 'diagram.figureDescription', {
      na: settingText(stack.nOutside),
      nb: settingText(stack.nFilm),
      nc: settingText(stack.nInside),
      thickness: settingText(stack.thicknessNm),
      angle: settingText(stack.angleDeg),
      refracted,
      count: magnitudes.length,
      last,
      amplitudes: magnitudes.map((m, n) => `|E${n}| = ${fourFigures(m)}`).join(', '),
    }),
  );

  el('rect', { x: 0, y: 0, width: WIDTH, height: SURFACE_Y, fill: '#e6f0fa' });
  el('rect', { x: 0, y: SURFACE_Y, width: WIDTH, height: film, fill: '#fbe3bd' });
  el('rect', { x: 0, y: back, width: WIDTH, height: HEIGHT - back, fill: '#e9f3e4' });
  const text = (x: number, y: number, content: string, attrs: Record<string, string | number> = {}) =>
    el('text', { x, y, 'font-size': 10, fill: '#1b1b1b', ...attrs }, content);
  text(4, 12, message(cat, 'diagram.mediumA', { n: settingText(stack.nOutside) }));
  // Under the film: θ_ri on the left, the film's own label on the right, then total reflection at the back.
  text(4, back + 13, `θri = ${refracted}`);
  text(WIDTH - 4, back + 27, message(cat, 'diagram.mediumB', { n: settingText(stack.nFilm), thickness: settingText(stack.thicknessNm) }), {
    'text-anchor': 'end',
  });
  text(4, HEIGHT - 5, message(cat, 'diagram.mediumC', { n: settingText(stack.nInside) }));
  if (flipTop) text(WIDTH - 4, 12, cat['diagram.flipTopNote'], { 'text-anchor': 'end', fill: '#8a1c00', 'font-weight': 'bold' });
  if (drawnDeg !== stack.angleDeg)
    text(WIDTH - 4, 24, message(cat, 'diagram.drawnAngle', { angle: settingText(drawnDeg) }), { 'text-anchor': 'end', 'font-size': 8.5 });

  // The normal, the incident ray and the angles.
  el('line', { x1: X0, y1: SURFACE_Y - 70, x2: X0, y2: back + 4, stroke: '#555', 'stroke-dasharray': '3 3', 'stroke-width': 0.7 });
  el('line', { x1: X0 - RAY * sinI, y1: SURFACE_Y - RAY * cosI, x2: X0, y2: SURFACE_Y, stroke: '#1b1b1b', 'stroke-width': 2.5 });
  text(X0 - RAY * sinI, SURFACE_Y - RAY * cosI - 5, cat['diagram.incident'], { 'font-size': 9 });
  const arc = 24;
  el('path', {
    d: `M ${X0} ${SURFACE_Y - arc} A ${arc} ${arc} 0 0 0 ${X0 - arc * sinI} ${SURFACE_Y - arc * cosI}`,
    fill: 'none',
    stroke: '#1b1b1b',
    'stroke-width': 0.8,
  });
  text(X0 - 4, SURFACE_Y - arc - 4, `θi = ${settingText(stack.angleDeg)}°`, { 'text-anchor': 'end' });
  const arcR = Math.min(film - 3, 16);
  el('path', {
    d: `M ${X0} ${SURFACE_Y + arcR} A ${arcR} ${arcR} 0 0 0 ${X0 + arcR * sinR} ${SURFACE_Y + arcR * Math.sqrt(1 - sinR * sinR)}`,
    fill: 'none',
    stroke: '#1b1b1b',
    'stroke-width': 0.8,
  });

  // The path through the film, and Δ between E0 and E1 (the path in the film minus its projection in a).
  const zigzag = Array.from({ length: 2 * last + 1 }, (_, k) => `${X0 + (k * step) / 2},${k % 2 ? back : SURFACE_Y}`);
  if (last > 0)
    el('polyline', {
      points: zigzag.join(' '),
      fill: 'none',
      stroke: '#7a4a00',
      'stroke-width': 1,
      ...(evanescent ? { 'stroke-dasharray': '2 2' } : {}),
    });
  const delta = opticalPathNm(stack);
  if (last > 0) {
    const along = step * sinI;
    el('line', {
      x1: X0 + step,
      y1: SURFACE_Y,
      x2: X0 + along * sinI,
      y2: SURFACE_Y - along * cosI,
      stroke: '#1f4fbf',
      'stroke-width': 0.8,
      'stroke-dasharray': '2 1.5',
    });
  }
  text(
    WIDTH - 4,
    HEIGHT - 20,
    message(cat, evanescent ? 'diagram.opticalPathEvanescent' : 'diagram.opticalPath', { delta: complexText(delta) }),
    { 'text-anchor': 'end', fill: '#1f4fbf' },
  );
  if (!evanescent && cosTransmitted.im !== 0) text(WIDTH - 4, back + 41, cat['diagram.backTotalReflection'], { 'text-anchor': 'end' });

  // The reflected beams, each as wide as its amplitude, with its amplitude written along it.
  const strongest = Math.max(...magnitudes, Number.MIN_VALUE);
  const spacing = step * cosI;
  magnitudes.forEach((m, n) => {
    const x = X0 + n * step;
    const length = Math.min(RAY, (WIDTH - 4 - x) / sinI, (SURFACE_Y - 4) / cosI);
    const width = Math.max(HAIRLINE, (MAX_BEAM_WIDTH * m) / strongest);
    const beam = el('line', {
      x1: x,
      y1: SURFACE_Y,
      x2: x + length * sinI,
      y2: SURFACE_Y - length * cosI,
      stroke: '#b03a00',
      'stroke-width': width,
      'data-beam': n,
    });
    beam.appendChild(
      svg(doc, 'title', {}, `${plainFormula(beamName(n))} = ${plainFormula(beamFormula(n, flipTop))}: |E${n}| = ${fourFigures(m)}`),
    );
    const withFormula = n < FORMULA_LABELS && (n === last || spacing >= 12);
    if (!withFormula && spacing < 7 && n > 0 && n !== last) return;
    const label = el('text', {
      transform: `translate(${x + 10 * sinI + (width / 2 + 2) * cosI} ${SURFACE_Y - 10 * cosI + (width / 2 + 2) * sinI}) rotate(${drawnDeg - 90})`,
      'font-size': 9,
      fill: '#1b1b1b',
      dy: 8,
    });
    label.append(...formulaNodes(doc, withFormula ? `${beamName(n)} = ${beamFormula(n, flipTop)}` : beamName(n), true));
  });
}

import { cAbs2 } from '../physics/complex.ts';
import type { FilmStack } from '../physics/filmReflectance.ts';
import { type FilmBeams, filmAngles, opticalPathNm } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { complexText, fourFigures, settingText } from './numberText.ts';
import { appendSvg, beamFormula, beamName, clearFigure, describeFigure, formulaNodes, plainFormula, svg } from './svgNodes.ts';

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

/** Where the figure draws its rays: the angles as drawn, the film's drawn thickness and the step between beams (SVG units). */
interface BeamGeometry {
  /** the incidence angle as drawn (within DRAWN_DEG), and its sine and cosine */
  readonly drawnDeg: number;
  readonly sinI: number;
  readonly cosI: number;
  /** sin θ_ri as drawn */
  readonly sinR: number;
  /** whether the film is evanescent (complex cos θ_ri) */
  readonly evanescent: boolean;
  /** the last beam's index N */
  readonly last: number;
  readonly film: number;
  /** the distance along the surface between one beam and the next */
  readonly step: number;
  /** the film's back surface */
  readonly back: number;
}

function beamGeometry(stack: FilmStack, evanescent: boolean, last: number): BeamGeometry {
  const drawnDeg = Math.min(DRAWN_DEG.max, Math.max(DRAWN_DEG.min, stack.angleDeg));
  const sinI = Math.sin(drawnDeg * DEG),
    cosI = Math.cos(drawnDeg * DEG);
  const sinR = evanescent ? Math.sin(EVANESCENT_DRAWN_DEG * DEG) : Math.min(0.95, (stack.nOutside * sinI) / stack.nFilm);
  const tanR = sinR / Math.sqrt(1 - sinR * sinR);
  const film = last > 0 ? Math.min(MAX_FILM, Math.max(MIN_FILM, (WIDTH - X0 - 70) / (2 * last * tanR))) : MAX_FILM;
  const step = 2 * film * tanR;
  return { drawnDeg, sinI, cosI, sinR, evanescent, last, film, step, back: SURFACE_Y + film };
}

/** A label in the figure's type, 10 units and near black unless `attrs` say otherwise. */
function label(figure: SVGSVGElement, x: number, y: number, content: string, attrs: Record<string, string | number> = {}) {
  return appendSvg(figure, 'text', { x, y, 'font-size': 10, fill: '#1b1b1b', ...attrs }, content);
}

/** Media a | b | c as bands with their indices, θ_ri under the film, and notes on the flipped top and the angle as drawn. */
function drawMedia(figure: SVGSVGElement, input: BeamFigureInput, g: BeamGeometry, refracted: string): void {
  const { stack, flipTop, catalogue: cat } = input;
  appendSvg(figure, 'rect', { x: 0, y: 0, width: WIDTH, height: SURFACE_Y, fill: '#e6f0fa' });
  appendSvg(figure, 'rect', { x: 0, y: SURFACE_Y, width: WIDTH, height: g.film, fill: '#fbe3bd' });
  appendSvg(figure, 'rect', { x: 0, y: g.back, width: WIDTH, height: HEIGHT - g.back, fill: '#e9f3e4' });
  label(figure, 4, 12, message(cat, 'diagram.mediumA', { n: settingText(stack.nOutside) }));
  // Under the film: θ_ri on the left, the film's own label on the right, then total reflection at the back.
  label(figure, 4, g.back + 13, `θri = ${refracted}`);
  const mediumB = message(cat, 'diagram.mediumB', { n: settingText(stack.nFilm), thickness: settingText(stack.thicknessNm) });
  label(figure, WIDTH - 4, g.back + 27, mediumB, { 'text-anchor': 'end' });
  label(figure, 4, HEIGHT - 5, message(cat, 'diagram.mediumC', { n: settingText(stack.nInside) }));
  if (flipTop) label(figure, WIDTH - 4, 12, cat['diagram.flipTopNote'], { 'text-anchor': 'end', fill: '#8a1c00', 'font-weight': 'bold' });
  if (g.drawnDeg !== stack.angleDeg)
    label(figure, WIDTH - 4, 24, message(cat, 'diagram.drawnAngle', { angle: settingText(g.drawnDeg) }), {
      'text-anchor': 'end',
      'font-size': 8.5,
    });
}

/** The normal, the incident ray and the angles θ_i and θ_ri. */
function drawIncidence(figure: SVGSVGElement, input: BeamFigureInput, g: BeamGeometry): void {
  const { sinI, cosI, sinR } = g;
  const arcStyle = { fill: 'none', stroke: '#1b1b1b', 'stroke-width': 0.8 };
  appendSvg(figure, 'line', {
    x1: X0,
    y1: SURFACE_Y - 70,
    x2: X0,
    y2: g.back + 4,
    stroke: '#555',
    'stroke-dasharray': '3 3',
    'stroke-width': 0.7,
  });
  appendSvg(figure, 'line', {
    x1: X0 - RAY * sinI,
    y1: SURFACE_Y - RAY * cosI,
    x2: X0,
    y2: SURFACE_Y,
    stroke: '#1b1b1b',
    'stroke-width': 2.5,
  });
  label(figure, X0 - RAY * sinI, SURFACE_Y - RAY * cosI - 5, input.catalogue['diagram.incident'], { 'font-size': 9 });
  const arc = 24;
  appendSvg(figure, 'path', {
    d: `M ${X0} ${SURFACE_Y - arc} A ${arc} ${arc} 0 0 0 ${X0 - arc * sinI} ${SURFACE_Y - arc * cosI}`,
    ...arcStyle,
  });
  label(figure, X0 - 4, SURFACE_Y - arc - 4, `θi = ${settingText(input.stack.angleDeg)}°`, { 'text-anchor': 'end' });
  const arcR = Math.min(g.film - 3, 16);
  appendSvg(figure, 'path', {
    d: `M ${X0} ${SURFACE_Y + arcR} A ${arcR} ${arcR} 0 0 0 ${X0 + arcR * sinR} ${SURFACE_Y + arcR * Math.sqrt(1 - sinR * sinR)}`,
    ...arcStyle,
  });
}

/** The path through the film, and Δ between E0 and E1 (the path in the film minus its projection in a). */
function drawFilmPath(figure: SVGSVGElement, input: BeamFigureInput, g: BeamGeometry, backTotalReflection: boolean): void {
  const { sinI, cosI, step, last, evanescent } = g;
  if (last > 0) {
    const zigzag = Array.from({ length: 2 * last + 1 }, (_, k) => `${X0 + (k * step) / 2},${k % 2 ? g.back : SURFACE_Y}`);
    const dashes: Record<string, string> = evanescent ? { 'stroke-dasharray': '2 2' } : {};
    appendSvg(figure, 'polyline', { points: zigzag.join(' '), fill: 'none', stroke: '#7a4a00', 'stroke-width': 1, ...dashes });
    const along = step * sinI;
    appendSvg(figure, 'line', {
      x1: X0 + step,
      y1: SURFACE_Y,
      x2: X0 + along * sinI,
      y2: SURFACE_Y - along * cosI,
      stroke: '#1f4fbf',
      'stroke-width': 0.8,
      'stroke-dasharray': '2 1.5',
    });
  }
  const cat = input.catalogue;
  const delta = message(cat, evanescent ? 'diagram.opticalPathEvanescent' : 'diagram.opticalPath', {
    delta: complexText(opticalPathNm(input.stack)),
  });
  label(figure, WIDTH - 4, HEIGHT - 20, delta, { 'text-anchor': 'end', fill: '#1f4fbf' });
  if (backTotalReflection) label(figure, WIDTH - 4, g.back + 41, cat['diagram.backTotalReflection'], { 'text-anchor': 'end' });
}

/** The reflected beams, each as wide as its amplitude, with its amplitude written along it. */
function drawBeams(figure: SVGSVGElement, flipTop: boolean, g: BeamGeometry, magnitudes: readonly number[]): void {
  const { sinI, cosI, step, last } = g;
  const doc = figure.ownerDocument;
  const strongest = Math.max(...magnitudes, Number.MIN_VALUE);
  const spacing = step * cosI;
  magnitudes.forEach((m, n) => {
    const x = X0 + n * step;
    const length = Math.min(RAY, (WIDTH - 4 - x) / sinI, (SURFACE_Y - 4) / cosI);
    const width = Math.max(HAIRLINE, (MAX_BEAM_WIDTH * m) / strongest);
    const beam = appendSvg(figure, 'line', {
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
    const text = appendSvg(figure, 'text', {
      transform: `translate(${x + 10 * sinI + (width / 2 + 2) * cosI} ${SURFACE_Y - 10 * cosI + (width / 2 + 2) * sinI}) rotate(${g.drawnDeg - 90})`,
      'font-size': 9,
      fill: '#1b1b1b',
      dy: 8,
    });
    text.append(...formulaNodes(doc, withFormula ? `${beamName(n)} = ${beamFormula(n, flipTop)}` : beamName(n), true));
  });
}

/**
 * The paper's Figure 1, live: media a | b | c with their indices, the incident ray at θ_i, the
 * path refracted at θ_ri (eq 1) through the film, the reflected beams E_0 … E_N (eqs 3, 7, 13),
 * each as wide as |E_n|, and the optical path difference Δ (eq 12) between E_0 and E_1.
 */
export function drawBeamFigure(figure: SVGSVGElement, input: BeamFigureInput, ids: { title: string; desc: string }): void {
  const { stack, catalogue: cat } = input;
  clearFigure(figure, WIDTH, HEIGHT);
  const { cosRefracted, cosTransmitted } = filmAngles(stack);
  const evanescent = cosRefracted.im !== 0;
  const magnitudes = beamMagnitudes(input.beams);
  const g = beamGeometry(stack, evanescent, magnitudes.length - 1);
  const refracted = evanescent ? cat['diagram.evanescent'] : `${(Math.acos(cosRefracted.re) / DEG).toFixed(1)}°`;
  const description = message(cat, 'diagram.figureDescription', {
    na: settingText(stack.nOutside),
    nb: settingText(stack.nFilm),
    nc: settingText(stack.nInside),
    thickness: settingText(stack.thicknessNm),
    angle: settingText(stack.angleDeg),
    refracted,
    count: magnitudes.length,
    last: g.last,
    amplitudes: magnitudes.map((m, n) => `|E${n}| = ${fourFigures(m)}`).join(', '),
  });
  describeFigure(figure, ids, cat['diagram.figureTitle'], description);
  drawMedia(figure, input, g, refracted);
  drawIncidence(figure, input, g);
  drawFilmPath(figure, input, g, !evanescent && cosTransmitted.im !== 0);
  drawBeams(figure, input.flipTop, g, magnitudes);
}

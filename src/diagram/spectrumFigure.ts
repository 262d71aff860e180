import { type FilmIndex, filmIndexAt } from '../physics/filmIndex.ts';
import type { FilmStack } from '../physics/filmReflectance.ts';
import type { Polarization } from '../physics/filmReflectance.ts';
import { filmBeams, opticalPathNm } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { WAVELENGTH_DOMAIN } from './diagramParameters.ts';
import { fourFigures, settingText } from './numberText.ts';
import { appendSvg, clearFigure, describeFigure } from './svgNodes.ts';

const WIDTH = 400;
const HEIGHT = 130;
const PLOT = { left: 34, right: 392, top: 8, bottom: 108 } as const;
/** Samples per fringe of R(λ) (a fringe spans about λ²/Δ), and the fewest and most over the band. */
const SAMPLES_PER_FRINGE = 16;
const MIN_SAMPLES = 451;
const MAX_SAMPLES = 4000;
const TICKS_NM = [400, 500, 600, 700, 800];

/** The axis' top: the curve's maximum rounded up to 1, 2 or 5 × 10^k (at least 0.01). */
function axisTop(max: number): number {
  const magnitude = 10 ** Math.floor(Math.log10(Math.max(max, 0.01)));
  return [1, 2, 5, 10].map((m) => m * magnitude).find((t) => t >= max * (1 + 1e-9)) ?? 10 * magnitude;
}

/** The diagram's film: real indices, the film's n_b possibly a function of λ. */
export type DiagramFilm = Omit<FilmStack, 'nFilm'> & { readonly nFilm: FilmIndex };

/** The diagram's film at one wavelength: its n_b(λ). */
export const diagramFilmAt = (film: DiagramFilm, lambdaNm: number): FilmStack => ({ ...film, nFilm: filmIndexAt(film.nFilm, lambdaNm) });

/** The diagram's film as the spectrum sees it. */
interface SpectrumFilm {
  readonly stack: DiagramFilm;
  readonly polarization: Polarization;
  readonly flipTop: boolean;
  readonly wavelengthNm: number;
}

/** R(λ) sampled over the band, R at the current wavelength, and the plot's map from (λ, R) to the figure. */
interface SpectrumCurve {
  readonly samples: readonly number[];
  readonly values: readonly number[];
  readonly current: number;
  /** the R axis' top */
  readonly top: number;
  readonly x: (lambdaNm: number) => number;
  readonly y: (reflectance: number) => number;
}

/**
 * R(λ) for the film (each λ with its own n_b(λ) and the same beams as the figure, flipTop
 * included), SAMPLES_PER_FRINGE samples a fringe within MIN_SAMPLES … MAX_SAMPLES.
 */
function spectrumCurve(film: SpectrumFilm): SpectrumCurve {
  const { min, max } = WAVELENGTH_DOMAIN;
  const reflectance = (l: number) => filmBeams(diagramFilmAt(film.stack, l), film.polarization, l, { flipTop: film.flipTop }).reflectance;
  const fringes = opticalPathNm(diagramFilmAt(film.stack, min)).re * (1 / min - 1 / max);
  const count = Math.min(MAX_SAMPLES, Math.max(MIN_SAMPLES, Math.ceil(SAMPLES_PER_FRINGE * fringes)));
  const samples = Array.from({ length: count }, (_, i) => min + ((max - min) * i) / (count - 1));
  const values = samples.map(reflectance);
  const current = reflectance(film.wavelengthNm);
  const top = axisTop(Math.max(...values, current));
  const x = (l: number) => PLOT.left + ((l - min) / (max - min)) * (PLOT.right - PLOT.left);
  const y = (r: number) => PLOT.bottom - (r / top) * (PLOT.bottom - PLOT.top);
  return { samples, values, current, top, x, y };
}

/** A label in the plot's type. */
function label(figure: SVGSVGElement, x: number, y: number, text: string, anchor = 'middle') {
  return appendSvg(figure, 'text', { x, y, 'font-size': 8, 'text-anchor': anchor, fill: '#1b1b1b' }, text);
}

/** The plot's frame, the λ ticks and the R axis' labels. */
function drawAxes(figure: SVGSVGElement, { x, y, top }: SpectrumCurve): void {
  appendSvg(figure, 'rect', {
    x: PLOT.left,
    y: PLOT.top,
    width: PLOT.right - PLOT.left,
    height: PLOT.bottom - PLOT.top,
    fill: '#fff',
    stroke: '#777',
    'stroke-width': 0.6,
  });
  for (const t of TICKS_NM) {
    appendSvg(figure, 'line', { x1: x(t), y1: PLOT.bottom, x2: x(t), y2: PLOT.bottom + 3, stroke: '#777', 'stroke-width': 0.6 });
    label(figure, x(t), PLOT.bottom + 11, String(t));
  }
  label(figure, PLOT.right, HEIGHT - 2, 'λ (nm)', 'end');
  for (const r of [0, top / 2, top]) label(figure, PLOT.left - 3, y(r) + 3, String(+r.toPrecision(3)), 'end');
  label(figure, PLOT.left + 3, PLOT.top + 9, 'R', 'start');
}

/** The curve, and the current wavelength marked on it with its λ and R. */
function drawCurve(figure: SVGSVGElement, { samples, values, current, x, y }: SpectrumCurve, wavelengthNm: number): void {
  appendSvg(figure, 'polyline', {
    points: samples.map((l, i) => `${x(l).toFixed(2)},${y(values[i]!).toFixed(2)}`).join(' '),
    fill: 'none',
    stroke: '#b03a00',
    'stroke-width': 1,
    'stroke-linejoin': 'round',
  });
  appendSvg(figure, 'line', {
    x1: x(wavelengthNm),
    y1: PLOT.top,
    x2: x(wavelengthNm),
    y2: PLOT.bottom,
    stroke: '#1f4fbf',
    'stroke-width': 0.8,
  });
  appendSvg(figure, 'circle', { cx: x(wavelengthNm), cy: y(current), r: 2.5, fill: '#1f4fbf', 'data-marker': '' });
  const right = wavelengthNm > (WAVELENGTH_DOMAIN.min + WAVELENGTH_DOMAIN.max) / 2;
  const text = `λ = ${settingText(wavelengthNm)} nm, R = ${fourFigures(current)}`;
  label(figure, x(wavelengthNm) + (right ? -4 : 4), PLOT.top + 18, text, right ? 'end' : 'start');
}

/**
 * R(λ) over the visible band for the diagram's film (each λ with its own n_b(λ) and the same
 * beams as the figure, flipTop included), sampled finely enough to show every fringe, with the
 * current wavelength marked.
 */
export function drawSpectrumFigure(
  figure: SVGSVGElement,
  film: SpectrumFilm,
  catalogue: Catalogue,
  ids: { title: string; desc: string },
): void {
  clearFigure(figure, WIDTH, HEIGHT);
  const curve = spectrumCurve(film);
  const description = message(catalogue, 'diagram.spectrumDescription', {
    wavelength: settingText(film.wavelengthNm),
    reflectance: fourFigures(curve.current),
  });
  describeFigure(figure, ids, catalogue['diagram.spectrumTitle'], description);
  drawAxes(figure, curve);
  drawCurve(figure, curve, film.wavelengthNm);
}

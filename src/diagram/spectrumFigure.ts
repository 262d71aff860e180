import { type FilmIndex, filmIndexAt } from '../physics/filmIndex.ts';
import type { FilmStack } from '../physics/filmReflectance.ts';
import type { Polarization } from '../physics/filmReflectance.ts';
import { filmBeams, opticalPathNm } from '../physics/reflectedBeams.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { WAVELENGTH_DOMAIN } from './diagramParameters.ts';
import { fourFigures, settingText } from './numberText.ts';
import { svg } from './svgNodes.ts';

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

/**
 * R(λ) over the visible band for the diagram's film (each λ with its own n_b(λ) and the same
 * beams as the figure, flipTop included), sampled finely enough to show every fringe, with the
 * current wavelength marked.
 */
export function drawSpectrumFigure(
  figure: SVGSVGElement,
  film: {
    readonly stack: DiagramFilm;
    readonly polarization: Polarization;
    readonly flipTop: boolean;
    readonly wavelengthNm: number;
  },
  catalogue: Catalogue,
  ids: { title: string; desc: string },
): void {
  const doc = figure.ownerDocument;
  const el = <K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number> = {}, text?: string) =>
    figure.appendChild(svg(doc, tag, attrs, text));
  figure.replaceChildren();
  figure.setAttribute('viewBox', `0 0 ${WIDTH} ${HEIGHT}`);
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

  el('title', { id: ids.title }, catalogue['diagram.spectrumTitle']);
  el(
    'desc',
    { id: ids.desc },
    message(catalogue, 'diagram.spectrumDescription', { wavelength: settingText(film.wavelengthNm), reflectance: fourFigures(current) }),
  );
  el('rect', {
    x: PLOT.left,
    y: PLOT.top,
    width: PLOT.right - PLOT.left,
    height: PLOT.bottom - PLOT.top,
    fill: '#fff',
    stroke: '#777',
    'stroke-width': 0.6,
  });
  const label = (lx: number, ly: number, text: string, anchor = 'middle') =>
    el('text', { x: lx, y: ly, 'font-size': 8, 'text-anchor': anchor, fill: '#1b1b1b' }, text);
  for (const t of TICKS_NM) {
    el('line', { x1: x(t), y1: PLOT.bottom, x2: x(t), y2: PLOT.bottom + 3, stroke: '#777', 'stroke-width': 0.6 });
    label(x(t), PLOT.bottom + 11, String(t));
  }
  label(PLOT.right, HEIGHT - 2, 'λ (nm)', 'end');
  for (const r of [0, top / 2, top]) label(PLOT.left - 3, y(r) + 3, String(+r.toPrecision(3)), 'end');
  label(PLOT.left + 3, PLOT.top + 9, 'R', 'start');
  el('polyline', {
    points: samples.map((l, i) => `${x(l).toFixed(2)},${y(values[i]!).toFixed(2)}`).join(' '),
    fill: 'none',
    stroke: '#b03a00',
    'stroke-width': 1,
    'stroke-linejoin': 'round',
  });
  el('line', { x1: x(film.wavelengthNm), y1: PLOT.top, x2: x(film.wavelengthNm), y2: PLOT.bottom, stroke: '#1f4fbf', 'stroke-width': 0.8 });
  el('circle', { cx: x(film.wavelengthNm), cy: y(current), r: 2.5, fill: '#1f4fbf', 'data-marker': '' });
  const right = film.wavelengthNm > (min + max) / 2;
  label(
    x(film.wavelengthNm) + (right ? -4 : 4),
    PLOT.top + 18,
    `λ = ${settingText(film.wavelengthNm)} nm, R = ${fourFigures(current)}`,
    right ? 'end' : 'start',
  );
}

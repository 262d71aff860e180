import type { MessageKey } from '../i18n/en.ts';
import type { FilmSpectrum } from './filmSpectrum.ts';
import { drawAxes, drawLine, prepareCanvas } from './plotCanvas.ts';

/** A round upper bound for the axis: 1, 2 or 5 × 10^k. */
function niceCeiling(v: number): number {
  const p = 10 ** Math.floor(Math.log10(v));
  return [1, 2, 5, 10].map((m) => m * p).find((c) => c >= v) ?? 10 * p;
}

/**
 * The spectra behind the probed colour over 380–830 nm: R(λ) and I_out(λ) = R·I_in on the
 * reflectance axis (I_in's peak = 1, so I_out ≤ R), and I_in's shape, scaled to the axis, dashed.
 */
export function drawSpectrumPlot(canvas: HTMLCanvasElement, s: FilmSpectrum, wavelengthLabel: string): void {
  const { ctx, width, height } = prepareCanvas(canvas);
  const top = niceCeiling(Math.max(1e-3, ...s.reflectance));
  const { px, py } = drawAxes(
    ctx,
    { width, height },
    { min: 380, max: 830, ticks: [400, 500, 600, 700, 800], label: wavelengthLabel },
    { min: 0, max: top, ticks: [0, top / 2, top], label: 'R' },
  );
  const series = (values: Float64Array, k = 1) => Array.from(values, (v, i) => [px(s.lambdasNm[i]!), py(k * v)] as const);
  ctx.setLineDash([3, 2]);
  drawLine(ctx, series(s.incident, top), SPECTRUM_LEGEND[2]![1], 1);
  ctx.setLineDash([]);
  drawLine(ctx, series(s.reflectance), SPECTRUM_LEGEND[0]![1]);
  drawLine(ctx, series(s.reflected), SPECTRUM_LEGEND[1]![1]);
  if (s.filmIndex) drawIndexAxis(ctx, s.lambdasNm, s.filmIndex, px, py(0), py(top));
}

/**
 * n_b(λ) of a dispersive film on a second scale: its range spans the plot's height, labelled at
 * the right edge with its largest and smallest values.
 */
function drawIndexAxis(
  ctx: CanvasRenderingContext2D,
  lambdasNm: Float64Array,
  n: Float64Array,
  px: (v: number) => number,
  bottom: number,
  top: number,
): void {
  const [low, high] = [Math.min(...n), Math.max(...n)];
  const span = Math.max(high - low, 1e-6);
  const y = (v: number) => bottom + ((v - low) / span) * (top - bottom);
  const color = SPECTRUM_LEGEND[3]![1];
  drawLine(
    ctx,
    Array.from(n, (v, i) => [px(lambdasNm[i]!), y(v)] as const),
    color,
    1,
  );
  ctx.fillStyle = color;
  ctx.textAlign = 'right';
  const right = px(lambdasNm[lambdasNm.length - 1]!) - 2;
  ctx.fillText(`n ${high.toFixed(4)}`, right, top + 10);
  ctx.fillText(`n ${low.toFixed(4)}`, right, bottom - 3);
}

/** The plot's series (their catalogue keys) and their colours, for a legend beside it. */
export const SPECTRUM_LEGEND: readonly (readonly [MessageKey, string])[] = [
  ['plots.legend.reflectance', '#7fb2ff'],
  ['plots.legend.reflected', '#ff7f9f'],
  ['plots.legend.incident', '#c9b458'],
  ['plots.legend.filmIndex', '#9fdf9f'],
];

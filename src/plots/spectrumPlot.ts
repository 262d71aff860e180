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
export function drawSpectrumPlot(canvas: HTMLCanvasElement, s: FilmSpectrum): void {
  const { ctx, width, height } = prepareCanvas(canvas);
  const top = niceCeiling(Math.max(1e-3, ...s.reflectance));
  const { px, py } = drawAxes(
    ctx,
    { width, height },
    { min: 380, max: 830, ticks: [400, 500, 600, 700, 800], label: 'wavelength (nm)' },
    { min: 0, max: top, ticks: [0, top / 2, top], label: 'R' },
  );
  const series = (values: Float64Array, k = 1) => Array.from(values, (v, i) => [px(s.lambdasNm[i]!), py(k * v)] as const);
  ctx.setLineDash([3, 2]);
  drawLine(ctx, series(s.incident, top), SPECTRUM_LEGEND[2]![1], 1);
  ctx.setLineDash([]);
  drawLine(ctx, series(s.reflectance), SPECTRUM_LEGEND[0]![1]);
  drawLine(ctx, series(s.reflected), SPECTRUM_LEGEND[1]![1]);
}

/** The plot's series and their colours, for a legend beside it. */
export const SPECTRUM_LEGEND: readonly (readonly [string, string])[] = [
  ['R(λ)', '#7fb2ff'],
  ['I_out = R·I_in', '#ff7f9f'],
  ['I_in (shape, peak at top)', '#c9b458'],
];

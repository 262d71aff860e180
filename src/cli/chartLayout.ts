import type { Rgb } from '../physics/colorConversions.ts';
import { ParameterError } from '../input/validate.ts';

/**
 * Where everything of a colour chart goes, in pixels from the top left; the PNG and the SVG
 * draw the same layout. Column i is thickness i of the table, so the strip starts at x = 0.
 * A 1-D chart is one strip `stripHeightPx` tall; a 2-D chart has one row of cells per angle,
 * angle 0 at the top, each cell 1 px wide and CELL_HEIGHT_2D_PX tall. Thickness ticks and
 * labels (nm) go in a margin below the strip, angle ticks and labels (degrees) in a margin to
 * its right.
 */

/** Height of one angle's row of cells in a 2-D chart. */
export const CELL_HEIGHT_2D_PX = 4;
/** The strip's height in a 1-D chart when --height is not given, and its allowed range. */
export const STRIP_HEIGHT_PX = { min: 1, max: 1000, fallback: 60 } as const;
/** Widest chart: one column per thickness. */
export const MAX_CHART_COLUMNS = 20_000;
/** Most pixels in a chart, margins included (64 MiB of RGBA). */
export const MAX_CHART_PIXELS = 16_777_216;
export const BOTTOM_MARGIN_PX = 16;
export const RIGHT_MARGIN_PX = 36;
const TICK_PX = 4;
/** Ticks at least this far apart: room for a label of 5 digits. */
const MIN_TICK_SPACING_PX = { x: 48, y: 12 } as const;

export interface ChartCell {
  readonly x: number;
  readonly y: number;
  readonly width: number;
  readonly height: number;
  readonly srgb8: Rgb;
  readonly hex: string;
}
export interface ChartTick {
  readonly x1: number;
  readonly y1: number;
  readonly x2: number;
  readonly y2: number;
}
/** A text whose top edge is at y; `anchor` says whether x is its start or its middle. */
export interface ChartLabel {
  readonly x: number;
  readonly y: number;
  readonly text: string;
  readonly anchor: 'start' | 'middle';
}
export interface ChartLayout {
  readonly width: number;
  readonly height: number;
  readonly cells: readonly ChartCell[];
  readonly ticks: readonly ChartTick[];
  readonly labels: readonly ChartLabel[];
}

/** One colour per cell: `colors[j][i]` is angle j (top down), thickness i (left to right). */
export interface ChartInput {
  readonly thicknessNm: readonly number[];
  /** `null` for a 1-D strip. */
  readonly anglesDeg: readonly number[] | null;
  readonly colors: readonly (readonly { srgb8: Rgb; hex: string }[])[];
  readonly stripHeightPx: number;
}

/** The smallest of 1, 2, 5 × 10^k that is at least `minimum`. */
function niceStep(minimum: number): number {
  const power = 10 ** Math.floor(Math.log10(minimum));
  return [1, 2, 5, 10].map((m) => m * power).find((s) => s >= minimum * (1 - 1e-9)) ?? 10 * power;
}

/** Indices of `values` (evenly spaced) that fall on round numbers at least `minPx` apart. */
function tickIndices(values: readonly number[], pxPerValue: number, minPx: number): number[] {
  const first = values[0] ?? 0;
  if (values.length < 2) return [0];
  const spacing = (values[1] ?? first) - first;
  const tick = niceStep(Math.max(spacing, (minPx / pxPerValue) * spacing));
  return values.flatMap((v, i) => (Math.abs(v / tick - Math.round(v / tick)) < 1e-6 ? [i] : []));
}

/** Checks the size before anything is allocated: a ParameterError names the flag that makes it too large. */
export function checkChartSize(columns: number, rows: number | null, stripHeightPx: number): { width: number; height: number } {
  if (columns > MAX_CHART_COLUMNS) {
    throw new ParameterError(
      '--step',
      `--step: gives ${columns} thicknesses, one column each; expected at most ${MAX_CHART_COLUMNS} for a chart (a larger step)`,
    );
  }
  const stripHeight = rows === null ? stripHeightPx : rows * CELL_HEIGHT_2D_PX;
  const width = columns + RIGHT_MARGIN_PX;
  const height = stripHeight + BOTTOM_MARGIN_PX;
  if (width * height > MAX_CHART_PIXELS) {
    const flag = rows === null ? '--height' : '--angles';
    throw new ParameterError(
      flag,
      `${flag}: the chart would be ${width} × ${height} px; expected at most ${MAX_CHART_PIXELS} pixels (fewer rows or thicknesses)`,
    );
  }
  return { width, height };
}

export function chartLayout(input: ChartInput): ChartLayout {
  const { thicknessNm, anglesDeg, colors } = input;
  const { width, height } = checkChartSize(thicknessNm.length, anglesDeg?.length ?? null, input.stripHeightPx);
  const stripHeight = height - BOTTOM_MARGIN_PX;
  const cellHeight = anglesDeg === null ? stripHeight : CELL_HEIGHT_2D_PX;
  const cells = colors.flatMap((row, j) =>
    row.map((c, i): ChartCell => ({ x: i, y: j * cellHeight, width: 1, height: cellHeight, srgb8: c.srgb8, hex: c.hex })),
  );
  const ticks: ChartTick[] = [];
  const labels: ChartLabel[] = [];
  const thicknessTicks = tickIndices(thicknessNm, 1, MIN_TICK_SPACING_PX.x);
  for (const i of thicknessTicks) {
    ticks.push({ x1: i, y1: stripHeight, x2: i, y2: stripHeight + TICK_PX });
    labels.push({ x: i, y: stripHeight + TICK_PX + 2, text: String(thicknessNm[i]), anchor: 'middle' });
  }
  // The unit after the last column, unless the last label reaches there.
  if ((thicknessTicks.at(-1) ?? 0) < thicknessNm.length - MIN_TICK_SPACING_PX.x / 2) {
    labels.push({ x: thicknessNm.length + 4, y: stripHeight + TICK_PX + 2, text: 'nm', anchor: 'start' });
  }
  if (anglesDeg !== null) {
    for (const j of tickIndices(anglesDeg, CELL_HEIGHT_2D_PX, MIN_TICK_SPACING_PX.y)) {
      const y = j * CELL_HEIGHT_2D_PX + CELL_HEIGHT_2D_PX / 2;
      const x = thicknessNm.length;
      ticks.push({ x1: x, y1: y, x2: x + TICK_PX, y2: y });
      labels.push({ x: x + TICK_PX + 2, y: Math.max(0, y - 3), text: String(anglesDeg[j]), anchor: 'start' });
    }
  }
  return { width, height, cells, ticks, labels };
}

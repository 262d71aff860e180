import type { FilmQuality } from '../../src/settings/filmQuality.ts';
import type { FilmSettings } from '../../src/settings/filmSettings.ts';
import type { ParityGroup } from '../harness/parityCase.ts';

export type EarlierModel = 'whiteWalls' | 'rgbProduct';

/** What each earlier model draws, as the tables name it. */
export const EARLIER_MODELS: Record<EarlierModel, string> = {
  whiteWalls: "the walls reflecting the light's white",
  rgbProduct:
    "the sky reflected and let through as an RGB product: the film's XYZ times the sky's colour (one table plane, one lookup a wall)",
};

/** One row of the benchmark as the page runs it (scripts/bench/page/benchPage.ts). */
export interface BenchRowSpec {
  /** `bubble`: the demo's view with these settings; `textured`: the same scene with a plain textured sphere instead */
  readonly kind: 'bubble' | 'textured';
  /**
   * An earlier model of the bubble's light, to time what the present one adds: `whiteWalls`, the walls
   * reflect the light's white whatever the environment (before environment reflections); `rgbProduct`,
   * the walls reflect and let through the sky as the film's XYZ times its RGB (one table plane, before
   * the film's environment matrix); null: today's
   */
  readonly earlierModel: EarlierModel | null;
  /**
   * An earlier model whose view of the same settings (a second view on the same renderer) draws a
   * frame with each of this row's (before and after it in turn), timed apart: frames taking turns, so that a busy machine's
   * noise hits both alike and their ratio holds (BenchRowResult.turns); null: none
   */
  readonly takesTurnsWith: EarlierModel | null;
  /** whether the changes are timed */
  readonly timesChanges: boolean;
  readonly settings: FilmSettings;
  readonly quality: FilmQuality;
  /** [width, height] of each frame-time column */
  readonly sizes: readonly (readonly [number, number])[];
  /** frames timed per size, at most, and the time budget that may cut them short (slow rows) */
  readonly frames: number;
  readonly frameBudgetMs: number;
  /** how often each change and its way back is timed, at most; whether the way back is timed too */
  readonly changeRepeats: number;
  readonly changesBack: boolean;
  /** cases whose film XYZ the shader computes for the error columns (none where the row measures no error) */
  readonly grids: readonly ParityGroup[];
}

export interface BenchRowResult {
  /**
   * navigation start to the first bubble frame drawn and read back; in a page reused for several
   * rows (BenchPlan.pagePerLane), a later row's from its call's start: a warm page's first frame,
   * not a cold one's
   */
  readonly firstFrameMs: number;
  /** the table's build in this view (null without a table) */
  readonly tableBuildMs: number | null;
  /** table rebuilds while the timed frames animated the field */
  readonly rebuildsWhileAnimating: number;
  /**
   * per size: median ms/frame and how many frames it is the median of; null: not timed (a smaller
   * size's frame outlasted the budget)
   */
  readonly frames: readonly (FrameTime | null)[];
  /**
   * per change of CHANGES: the change applied → the next frame drawn and read back, ms (median of
   * the changes and changes back); null: not timed (the textured sphere, or the row's frame
   * outlasts the budget)
   */
  readonly changeToFrameMs: readonly (number | null)[];
  /** the earlier model's view, where the row takes turns with one: its frame per size (as `frames`) */
  readonly turns: { readonly model: EarlierModel; readonly frames: readonly (FrameTime | null)[] } | null;
  /** per grid of the spec, per case: XYZ */
  readonly xyz: readonly number[][][];
}

/**
 * A size's frame time: the median of `count` frames drawn at that size, or, where one frame there
 * would outlast the budget, the line through one frame at each of `fittedFrom` (smaller sizes)
 * taken to this size's pixels.
 */
export type FrameTime =
  | { readonly medianMs: number; readonly count: number }
  | { readonly medianMs: number; readonly fittedFrom: readonly (readonly [number, number])[] };

/** A frame is fitted rather than drawn where it would take this many budgets: one somewhat over costs little more than the fit. */
export const FIT_OVER_BUDGET = 4;

/**
 * The sizes, a quarter and a half of a size's width and height, whose frames a slow row's frame
 * time is fitted from: 1/16 and 1/4 of its pixels. Smaller ones would cost less but fit worse: a CPU
 * rasteriser shares a tiny frame's fragments among fewer threads, so its cost per pixel is higher.
 */
export const fitSizes = ([width, height]: readonly [number, number]): [[number, number], [number, number]] => [
  [Math.round(width / 4), Math.round(height / 4)],
  [Math.round(width / 2), Math.round(height / 2)],
];

/**
 * A frame's time at `pixels`, on the line through two frames' [pixels, ms]: a fixed cost (the
 * scene's draws, a simulation's steps) plus a cost per pixel (the film's fragments), not below
 * the larger measured frame.
 */
export function fittedFrameMs(points: readonly [readonly [number, number], readonly [number, number]], pixels: number): number {
  const [[p1, t1], [p2, t2]] = points;
  if (!(p2 > p1)) throw new Error(`fittedFrameMs: the second frame's pixels (${p2}) must exceed the first's (${p1})`);
  return Math.max(t2, t2 + ((t2 - t1) * (pixels - p2)) / (p2 - p1));
}

/** [width, height] of a row's first frame: small, so that it costs the compile and the table's build but few fragments. */
export const FIRST_FRAME_SIZE = [64, 36] as const;

/**
 * The changes timed per row, as a user makes them in the panel: n film, the light, the
 * polarisation, the range; each there and back to the row's own value (a water row's n film
 * change is 1.4 and back to water: a change of the film material).
 */
export const CHANGES: readonly { readonly name: string; readonly values: (own: FilmSettings) => readonly Partial<FilmSettings>[] }[] = [
  { name: 'n film', values: (own) => [{ nFilm: 1.4 }, { nFilm: own.nFilm }] },
  { name: 'light', values: (own) => [{ illuminant: 'D93' }, { illuminant: own.illuminant }] },
  { name: 'polarisation', values: (own) => [{ polarization: 's' }, { polarization: own.polarization }] },
  { name: 'range', values: (own) => [{ thicknessRangeNm: 1200 }, { thicknessRangeNm: own.thicknessRangeNm }] },
];

declare global {
  interface Window {
    benchRow?: (spec: BenchRowSpec) => Promise<BenchRowResult>;
  }
}

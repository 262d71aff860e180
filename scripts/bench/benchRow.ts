import type { FilmQuality } from '../../src/render/filmQuality.ts';
import type { FilmSettings } from '../../src/render/filmSettings.ts';
import type { ParityGroup } from '../../tests/e2e/harness/parityCase.ts';

/** One row of the benchmark as the page runs it (scripts/bench/page/benchPage.ts). */
export interface BenchRowSpec {
  /** `bubble`: the demo's view with these settings; `textured`: the same scene with a plain textured sphere instead */
  readonly kind: 'bubble' | 'textured';
  readonly settings: FilmSettings;
  readonly quality: FilmQuality;
  /** [width, height] of each frame-time column */
  readonly sizes: readonly (readonly [number, number])[];
  /** frames timed per size, at most, and the time budget that may cut them short (slow rows) */
  readonly frames: number;
  readonly frameBudgetMs: number;
  /** cases whose film XYZ the shader computes for the error columns (none for `textured`) */
  readonly grids: readonly ParityGroup[];
}

export interface BenchRowResult {
  /** navigation start to the first bubble frame drawn and read back */
  readonly firstFrameMs: number;
  /** the table's build in this view (null without a table) */
  readonly tableBuildMs: number | null;
  /** table rebuilds while the timed frames animated the field */
  readonly rebuildsWhileAnimating: number;
  /** per size: median ms/frame and how many frames it is the median of */
  readonly frames: readonly { readonly medianMs: number; readonly count: number }[];
  /** per grid, per case: XYZ */
  readonly xyz: readonly number[][][];
}

declare global {
  interface Window {
    benchRow?: (spec: BenchRowSpec) => BenchRowResult;
  }
}

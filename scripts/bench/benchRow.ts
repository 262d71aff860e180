import type { FilmQuality } from '../../src/render/filmQuality.ts';
import type { FilmSettings } from '../../src/render/filmSettings.ts';
import type { ParityGroup } from '../../src/render/parityCase.ts';

/** One row of the benchmark as the page runs it (scripts/bench/page/benchPage.ts). */
export interface BenchRowSpec {
  /** `bubble`: the demo's view with these settings; `textured`: the same scene with a plain textured sphere instead */
  readonly kind: 'bubble' | 'textured';
  /** false: the walls reflect the light's white whatever the environment (the model before environment reflections), to time what they add */
  readonly reflections: boolean;
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
  /** per change of CHANGES: the change applied → the next frame drawn and read back, ms (median of 3) */
  readonly changeToFrameMs: readonly number[];
  /** per grid, per case: XYZ */
  readonly xyz: readonly number[][][];
}

/** The changes timed per row, as a user makes them in the panel: n film, the light, the polarisation, the range. */
export const CHANGES: readonly { readonly name: string; readonly values: readonly Partial<FilmSettings>[] }[] = [
  { name: 'n film', values: [{ nFilm: 1.4 }, { nFilm: 1.33 }] },
  { name: 'light', values: [{ illuminant: 'D93' }, { illuminant: 'D65' }] },
  { name: 'polarisation', values: [{ polarization: 's' }, { polarization: 'unpolarized' }] },
  { name: 'range', values: [{ thicknessRangeNm: 1200 }, { thicknessRangeNm: 800 }] },
];

declare global {
  interface Window {
    benchRow?: (spec: BenchRowSpec) => Promise<BenchRowResult>;
  }
}

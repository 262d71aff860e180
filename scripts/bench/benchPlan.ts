/**
 * How much the benchmark measures: the full run (the figures in docs/benchmarks.md) or the smoke
 * run (`--smoke`: every figure and each kind of row once (BenchRow.smoke), at a small size, to show
 * that each one runs and gives finite figures; its times mean nothing). Its own ports: 5173 is the dev server's, 5180 and 5181
 * the browser tests' (tests/e2e/servers.ts), so the bench runs beside either; `--port` moves them.
 */
import type { ParityGroup } from '../harness/parityCase.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../src/settings/filmQuality.ts';
import type { DefaultViewPlan } from './defaultView.ts';
import type { FlowSpeedPlan } from './flowSpeed.ts';
import type { NodeFiguresPlan } from './nodeFigures.ts';

export interface BenchPlan {
  readonly smoke: boolean;
  /** [width, height] of each frame-time column */
  readonly sizes: readonly (readonly [number, number])[];
  /** frames timed per size at most; the budget cuts a slow row's frames and changes short */
  readonly frames: number;
  readonly frameBudgetMs: number;
  /** how often each change and its way back is timed, at most (fewer where they outlast the budget); whether the way back is timed */
  readonly changeRepeats: number;
  readonly changesBack: boolean;
  /** every `gridStride`-th film of each error grid */
  readonly gridStride: number;
  readonly materials: { readonly width: number; readonly height: number; readonly frames: number };
  /** the sphere of the node figures on WebGPURenderer (nodeFigures.ts): its size, and the frames timed per material and backend */
  readonly node: NodeFiguresPlan;
  /** the built demo's viewport, and how long after a panel change's frame in full its tasks are still counted */
  /** the built demo page: its size, how long each panel change's frame is watched after, and whether each change is made there and back twice (the second time's programs) or once */
  readonly demo: { readonly width: number; readonly height: number; readonly windowMs: number; readonly panelTwice: boolean };
  /** the built demo's default view against the swirl: their size, how long each animates, and how long the governor's settling is left out of the frame interval */
  readonly defaultView: DefaultViewPlan;
  /** the flowing film's simulation speed, on the GPU and in the twin (flowSpeed.ts) */
  readonly flowSpeed: FlowSpeedPlan;
  /**
   * How many stages run at once: 1 in the full run, whose times are its figures; 2 in the smoke,
   * whose times mean nothing, so that its pages compile on both cores and the builds overlap them.
   */
  readonly concurrency: number;
  /**
   * Whether each lane (a runner of `concurrency`) runs its rows in one page, changing the row in
   * place (benchRow called again), rather than in a fresh page (and WebGL context) per row. false
   * in the full run: its first frame is a cold page's and its times are the published figures.
   * true in the smoke: a later row's first frame is then timed from its call in a warm page.
   */
  readonly pagePerLane: boolean;
  readonly devPort: number;
  readonly previewPort: number;
  readonly resultsFile: string;
}

/**
 * A row's quality in the smoke run: its table at most 128 texels wide and 16 rows per half, so a
 * table row builds in a moment and still runs every step of its kind (fill, precision, layout
 * powers), and likewise the node figures' tables; the smoke checks that each row runs and gives finite figures, not their values.
 */
export const smokeQuality = (q: FilmQuality): FilmQuality => ({
  ...q,
  table: { ...q.table, width: Math.min(q.table.width, 128), rows: Math.min(q.table.rows, 16) },
});

export const FULL_PLAN: BenchPlan = {
  smoke: false,
  sizes: [
    [1280, 720],
    [1920, 1080],
  ],
  frames: 20,
  frameBudgetMs: 1000,
  changeRepeats: 2,
  changesBack: true,
  gridStride: 1,
  materials: { width: 1280, height: 720, frames: 10 },
  node: {
    width: 1280,
    height: 720,
    frames: 10,
    quality: DEFAULT_FILM_QUALITY,
    changesAlsoAt: [
      { width: 320, height: 180, gpuApart: false },
      { width: 1280, height: 720, gpuApart: true },
    ],
  },
  demo: { width: 1280, height: 720, windowMs: 1000, panelTwice: true },
  defaultView: { width: 1280, height: 720, seconds: 30, settlingMs: 3000, firstFrameLoads: 5 },
  flowSpeed: { grids: [64, 128], warmUpSteps: 3, batchSteps: 4, batches: 5 },
  concurrency: 1,
  pagePerLane: false,
  devPort: 5192,
  previewPort: 5193,
  resultsFile: 'bench-results.json',
};

export const SMOKE_PLAN: BenchPlan = {
  smoke: true,
  sizes: [[160, 90]],
  frames: 1,
  frameBudgetMs: 3000,
  changeRepeats: 1,
  changesBack: false,
  // ~60 films of each error grid, every thickness and angle range still met: enough to show the error columns run and are finite.
  gridStride: 64,
  materials: { width: 160, height: 90, frames: 1 },
  node: { width: 160, height: 90, frames: 1, quality: smokeQuality(DEFAULT_FILM_QUALITY), changesAlsoAt: [] },
  demo: { width: 320, height: 180, windowMs: 100, panelTwice: false },
  defaultView: { width: 320, height: 180, seconds: 1, settlingMs: 500, firstFrameLoads: 1 },
  flowSpeed: { grids: [8, 16], warmUpSteps: 1, batchSteps: 1, batches: 1 },
  concurrency: 2,
  pagePerLane: true,
  devPort: 5194,
  previewPort: 5195,
  resultsFile: '.scratch/bench-smoke-results.json',
};

/** The plan with the benchmark's own servers on `devPort` and the port after it (`--port`). */
export const withPorts = (plan: BenchPlan, devPort: number | null): BenchPlan =>
  devPort === null ? plan : { ...plan, devPort, previewPort: devPort + 1 };

/** The plan's share of a grid: every `stride`-th film. */
export const thinnedGrid = (g: ParityGroup, stride: number): ParityGroup =>
  stride === 1 ? g : { ...g, inputs: g.inputs.filter((_, i) => i % stride === 0) };

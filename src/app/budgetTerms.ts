/**
 * The frame budget's terms (docs/governor.md): the budgets, the grids and pixel ratios the governor
 * chooses among, and what its decision (frameBudget.ts) reads and gives.
 */

/** A frame at 60 Hz (ms): the budget where the machine holds it. */
export const FAST_BUDGET_MS = 1000 / 60;
/** 4 frames a second (ms): the most the budget is anywhere. */
export const SLOW_BUDGET_MS = 250;
/**
 * Elsewhere the budget is this many times the bubble's own frame at the ladder's pixel ratio (its
 * frame with the film left out: what a painted field's frame costs there), within FAST_BUDGET_MS
 * and SLOW_BUDGET_MS: the simulated film adds at most a quarter to a frame.
 */
export const DRAW_SHARE = 1.25;
/** The grid the governor starts on (the largest of its grids not above it): cheap to make and to step on any machine, and its step's cost, measured, predicts the other grids'. */
export const START_GRID = 32;
/** The grids the governor chooses among (cells per cube face side), within GOVERNED_GRID: each about √2 times the one before, so a step's 6N² fragments about double from one to the next. */
export const GOVERNED_GRIDS = [16, 24, 32, 48, 64, 96, 128, 192, 256] as const;
/** The governor's grid range (a user may ask for any grid of FLOW_PARAMETERS, 4–256). */
export const GOVERNED_GRID = { min: 16, max: 256 } as const;
/** The pixel ratios the governor chooses among below the device's (shownPixelRatio), which tops them. */
export const GOVERNED_PIXEL_RATIOS = [0.5, 0.75, 1, 1.5] as const;
/** The pixel ratios the governor chooses among, ascending, on a device drawn at `shown` (shownPixelRatio): the governed ones below it, and it. */
export const governedPixelRatios = (shown: number): readonly number[] => [...GOVERNED_PIXEL_RATIOS.filter((r) => r < shown), shown];
/** The most steps per frame the governor gives. */
export const GOVERNED_MAX_STEPS = 64;

/** What one frame cost: its interval, the simulation's own time in it and the steps taken (both of all the views governed). */
export interface FrameSample {
  readonly intervalMs: number;
  readonly simMs: number;
  readonly steps: number;
  /** The bubbles' draw as the GPU timed it, where it can (else the interval less the simulation stands for it: an upper bound, vsync's wait included). */
  readonly drawMs?: number | undefined;
}

/** What the governor may choose, and what it must not touch. */
export interface BudgetLimits {
  /** The grids it may choose, ascending (GOVERNED_GRIDS), or the one a user gave. */
  readonly grids: readonly number[];
  /** The pixel ratios it may choose, ascending, or the one a user gave. */
  readonly pixelRatios: readonly number[];
  /** Steps per frame: the most it gives, and the number a frame that holds its budget takes at least (if real time asks for them). */
  readonly maxStepsPerFrame: number;
  readonly baseStepsPerFrame: number;
  /** A user's steps per frame (Infinity: all the time asks for, as with a given simSpeed); else the governor's. */
  readonly fixedStepsPerFrame: number | null;
  /** Film seconds per step at a grid, and film seconds per second wanted. */
  readonly stepSeconds: (gridN: number) => number;
  readonly simSpeed: number;
  /** The views sharing the budget, each taking the steps. */
  readonly views: number;
}

export interface BudgetChoice {
  readonly gridN: number;
  readonly stepsPerFrame: number;
  readonly pixelRatio: number;
  /** The budget chosen (ms): FAST_BUDGET_MS, or DRAW_SHARE times the bubble's own frame within FAST_BUDGET_MS–SLOW_BUDGET_MS. */
  readonly budgetMs: number;
}

/** A rung of the ladder: a grid and a pixel ratio. */
export interface Rung {
  readonly gridN: number;
  readonly pixelRatio: number;
}

export interface BudgetState {
  readonly choice: BudgetChoice;
  /** Rungs (by key) found too slow: never tried again. */
  readonly banned: readonly string[];
  /** The frames since the last change: count, ms, sim ms, steps. */
  readonly window: {
    readonly frames: number;
    readonly ms: number;
    readonly simMs: number;
    readonly steps: number;
    readonly drawMs: number | null;
  };
  /** The simulation's ms and steps summed by grid, and the draw's ms and frames by pixel ratio, over every window judged: their means are the costs. */
  readonly stepMs: Costs;
  readonly drawMs: Costs;
  /** Whether the steps per frame are still the first frames' one step. */
  readonly probing: boolean;
  /** The governor's one rise, once made: the choice it rose from (known to hold) and the rung it rose to. */
  readonly rose: { readonly from: BudgetChoice; readonly to: string } | null;
  /** Whether a window may still go up: until the first one judged after the start's decision. */
  readonly mayRise: boolean;
  /** The windows in a row that overran. */
  readonly overruns: number;
}

/** A cost summed over what it was measured in (steps, frames). */
export interface Sum {
  readonly ms: number;
  readonly count: number;
}
export type Costs = Readonly<Record<number, Sum>>;
export const added = (costs: Costs, at: number, ms: number, count: number): Costs =>
  count > 0 ? { ...costs, [at]: { ms: (costs[at]?.ms ?? 0) + ms, count: (costs[at]?.count ?? 0) + count } } : costs;
export const meanOf = (costs: Costs, at: number): number => costs[at]!.ms / costs[at]!.count;

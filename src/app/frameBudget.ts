/**
 * The frame budget's decision (docs/governor.md): from what the animating frames cost, the flow's
 * grid, its steps per frame and the drawing buffer's pixel ratio, within the budget. A pure function
 * of the timings it is fed and its previous state; FrameGovernor measures and applies.
 */

/** A frame at 60 Hz (ms): the budget where the machine holds it at full quality. */
export const FAST_BUDGET_MS = 1000 / 60;
/** 4 frames a second (ms): the budget elsewhere, with quality lowered only as far as needed. */
export const SLOW_BUDGET_MS = 250;
/** The grids the governor chooses among (cells per cube face side), within GOVERNED_GRID: each about √2 times the one before, so a step's 6N² fragments about double from one to the next. */
export const GOVERNED_GRIDS = [16, 24, 32, 48, 64, 96, 128, 192, 256] as const;
/** The governor's grid range (a user may ask for any grid of FLOW_PARAMETERS, 4–256). */
export const GOVERNED_GRID = { min: 16, max: 256 } as const;
/** The pixel ratios the governor chooses among, at most the device's (and 2). */
export const GOVERNED_PIXEL_RATIOS = [0.5, 0.75, 1, 1.5, 2] as const;
/** The most steps per frame the governor gives. */
export const GOVERNED_MAX_STEPS = 64;

/**
 * A window is judged once it holds this many frames and lasts this long (ms) at the 60 Hz budget,
 * SLOW_WINDOW_MS at the slow one (a few frames, so that one late frame, a busy moment of the machine,
 * is not an overrun); the first frames at full quality are judged once they last two slow budgets,
 * however few (one such frame says the machine cannot hold 60 fps).
 */
const MIN_FRAMES = 2;
const MIN_WINDOW_MS = 500;
const SLOW_WINDOW_MS = 1500;
/**
 * A window's mean frame above this many budgets is an overrun: the choice goes down after two in a
 * row (a busy moment of the machine is not the machine), or after one above CLEAR_OVERRUN budgets,
 * or in the first frames.
 */
const OVERRUN = 1.25;
const CLEAR_OVERRUN = 2;
/** A window's mean frame within this many budgets holds it. */
const HOLDS = 1.1;
/** The steps fill this share of the budget (less the draw): a frame planned at 0.8 budgets overruns only 1.5 times as long. */
const STEP_FILL = 0.8;
/**
 * The choice goes up only to a rung predicted within this share of the budget, after a window
 * this long (ms), and only once in a governor's life: a second rise would follow the noise of the
 * costs measured, not the machine.
 */
const UP_MARGIN = 0.6;
const UP_WINDOW_MS = 1000;
/**
 * The share of a measured cost taken to stay when the grid or the pixels shrink: a fixed cost
 * per draw (a CPU rasteriser's) that a smaller target does not save. Smaller than the truth
 * errs on the side of slower frames; a second grid measured replaces it with the fit.
 */
const FIXED_SHARE = 0.5;

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
  /** The budget chosen (ms): FAST_BUDGET_MS or SLOW_BUDGET_MS. */
  readonly budgetMs: number;
}

/** A rung of the ladder: a grid and a pixel ratio. */
interface Rung {
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
  readonly stepMs: Readonly<Record<number, Sum>>;
  readonly drawMs: Readonly<Record<number, Sum>>;
  /** Whether the steps per frame are still the first frames' one step. */
  readonly probing: boolean;
  /** The governor's one rise, once made: the choice it rose from (known to hold) and the rung it rose to. */
  readonly rose: { readonly from: BudgetChoice; readonly to: string } | null;
  /** The windows in a row that overran. */
  readonly overruns: number;
}

/** A cost summed over what it was measured in (steps, frames). */
interface Sum {
  readonly ms: number;
  readonly count: number;
}
type Costs = Readonly<Record<number, Sum>>;
const added = (costs: Costs, at: number, ms: number, count: number): Costs =>
  count > 0 ? { ...costs, [at]: { ms: (costs[at]?.ms ?? 0) + ms, count: (costs[at]?.count ?? 0) + count } } : costs;
const meanOf = (costs: Costs, at: number): number => costs[at]!.ms / costs[at]!.count;

const key = (r: Rung): string => `${r.gridN}@${r.pixelRatio}`;
const EMPTY_WINDOW = { frames: 0, ms: 0, simMs: 0, steps: 0, drawMs: 0 };

/**
 * The rungs from full quality down: every grid with every ratio, ordered by the cells and pixels
 * they keep (a halved grid side counts as a halved pixel ratio), a tie keeping the finer grid.
 */
export function ladder(limits: Pick<BudgetLimits, 'grids' | 'pixelRatios'>): readonly Rung[] {
  const top = { g: Math.max(...limits.grids), r: Math.max(...limits.pixelRatios) };
  const score = (x: Rung) => Math.log2(x.gridN / top.g) + Math.log2(x.pixelRatio / top.r);
  const rungs = limits.grids.flatMap((gridN) => limits.pixelRatios.map((pixelRatio) => ({ gridN, pixelRatio })));
  return rungs.sort((a, b) => score(b) - score(a) || b.gridN - a.gridN);
}

/** The first choice: full quality, one step a frame until frames are measured. */
export function initialBudget(limits: BudgetLimits): BudgetState {
  const top = ladder(limits)[0]!;
  return {
    choice: { ...top, stepsPerFrame: limits.fixedStepsPerFrame ?? 1, budgetMs: FAST_BUDGET_MS },
    banned: [],
    window: EMPTY_WINDOW,
    stepMs: {},
    drawMs: {},
    probing: true,
    rose: null,
    overruns: 0,
  };
}

/**
 * A cost measured at `at` (the nearest measured), carried to `x` by cells or pixels (x²): in full
 * going up (an upper bound, as a fixed part does not grow), FIXED_SHARE kept going down.
 */
function carried(measured: Costs, x: number): number | undefined {
  const known = Object.keys(measured).map(Number);
  if (known.length === 0) return undefined;
  const at = known.reduce((a, b) => (Math.abs(b - x) < Math.abs(a - x) || (Math.abs(b - x) === Math.abs(a - x) && b > a) ? b : a));
  const ms = meanOf(measured, at);
  const s = (x / at) ** 2;
  return x >= at ? ms * s : ms * (FIXED_SHARE + (1 - FIXED_SHARE) * s);
}

/**
 * A step's cost at a grid (docs/flow.md's cost model: a + b·N², a fixed cost per pass and one per
 * cell): measured; between two grids measured, the fit through the nearest below and above; below
 * them all, the fit through the two smallest; above them all (or with one grid measured), carried
 * (an upper bound going up).
 */
function predictedStepMs(stepMs: Costs, gridN: number): number | undefined {
  if (stepMs[gridN] !== undefined) return meanOf(stepMs, gridN);
  const known = Object.keys(stepMs)
    .map(Number)
    .sort((a, b) => a - b);
  const above = known.findIndex((n) => n > gridN);
  if (known.length < 2 || above < 0) return carried(stepMs, gridN);
  const [n1, n2] = above === 0 ? [known[0]!, known[1]!] : [known[above - 1]!, known[above]!];
  const [m1, m2] = [meanOf(stepMs, n1), meanOf(stepMs, n2)];
  const b = Math.max(0, (m1 - m2) / (n1 * n1 - n2 * n2));
  const a = Math.max(0, m1 - b * n1 * n1);
  return a + b * gridN * gridN;
}

/** The steps a frame takes at a rung: those that fit the budget, no more than real time asks, at least one (a user's number as given). */
function stepsAt(s: BudgetState, rung: Rung, budgetMs: number, limits: BudgetLimits, holds: boolean): number {
  if (limits.fixedStepsPerFrame !== null) return limits.fixedStepsPerFrame;
  const measured = predictedStepMs(s.stepMs, rung.gridN);
  // No step measured yet (the first frames' film time asked for none): one, until the next window tells.
  if (measured === undefined) return 1;
  const step = measured * limits.views;
  const draw = carried(s.drawMs, rung.pixelRatio) ?? 0;
  const filmMsPerStep = (1000 * limits.stepSeconds(rung.gridN)) / limits.simSpeed;
  const fit = step > 0 ? Math.floor((STEP_FILL * budgetMs - draw) / step) : limits.maxStepsPerFrame;
  // Real time: n steps cover the frame they make, n·film ≥ draw + n·step.
  const realTime = filmMsPerStep > step ? Math.ceil(Math.max(draw, 1) / (filmMsPerStep - step)) : Infinity;
  const floor = holds ? Math.min(realTime, limits.baseStepsPerFrame) : 1;
  return Math.max(1, Math.min(limits.maxStepsPerFrame, Math.max(floor, Math.min(fit, realTime))));
}

/** A rung's frame with `steps` steps in each view, predicted (a cost nothing measured tells counts 0: the window after tells). */
function predictedFrameMs(s: BudgetState, rung: Rung, steps: number, limits: BudgetLimits): number {
  const step = predictedStepMs(s.stepMs, rung.gridN) ?? 0;
  const draw = carried(s.drawMs, rung.pixelRatio) ?? 0;
  return draw + Math.min(steps, GOVERNED_MAX_STEPS) * step * limits.views;
}

const rungIndex = (rungs: readonly Rung[], x: Rung): number => rungs.findIndex((r) => r.gridN === x.gridN && r.pixelRatio === x.pixelRatio);

const changed = (a: BudgetChoice, b: BudgetChoice): boolean =>
  a.gridN !== b.gridN || a.pixelRatio !== b.pixelRatio || a.stepsPerFrame !== b.stepsPerFrame || a.budgetMs !== b.budgetMs;

/**
 * The governor's next state after a frame (docs/governor.md). Frames gather into a window; once it
 * holds MIN_FRAMES frames over MIN_WINDOW_MS it is judged by its mean, and its costs join those
 * measured before. An overrun (above OVERRUN budgets) bans the rung with every rung above it and
 * goes down to the best rung left whose frame with one step is predicted within the budget (the
 * lowest if none is). The first window that holds sets the steps per frame; a window held for
 * UP_WINDOW_MS goes up, once in the governor's life, to a rung not banned predicted within
 * UP_MARGIN of the budget. The budget is FAST_BUDGET_MS until full quality overruns it, then
 * SLOW_BUDGET_MS for good. The steps fill what the draw leaves of the budget, no more than real time asks.
 */
export function nextBudget(state: BudgetState, sample: FrameSample, limits: BudgetLimits): BudgetState {
  const w = {
    frames: state.window.frames + 1,
    ms: state.window.ms + sample.intervalMs,
    simMs: state.window.simMs + sample.simMs,
    steps: state.window.steps + sample.steps,
    // The GPU's draw time only while every frame of the window has it.
    drawMs: state.window.drawMs === null || sample.drawMs === undefined ? null : state.window.drawMs + sample.drawMs,
  };
  const s: BudgetState = { ...state, window: w };
  const windowMs = state.choice.budgetMs === SLOW_BUDGET_MS ? SLOW_WINDOW_MS : MIN_WINDOW_MS;
  const ready = state.probing
    ? w.ms >= 2 * SLOW_BUDGET_MS || (w.frames >= MIN_FRAMES && w.ms >= MIN_WINDOW_MS)
    : w.frames >= MIN_FRAMES && w.ms >= windowMs;
  if (!ready) return s;
  const { choice } = s;
  const frameMs = w.ms / w.frames;
  const measured: BudgetState = {
    ...s,
    stepMs: added(s.stepMs, choice.gridN, w.simMs, w.steps),
    drawMs: added(s.drawMs, choice.pixelRatio, w.drawMs ?? Math.max(0, w.ms - w.simMs), w.frames),
  };
  const rungs = ladder(limits);
  // A choice off the ladder (limits changed under it) counts as its top.
  const here = Math.max(0, rungIndex(rungs, choice));
  const overruns = frameMs > OVERRUN * choice.budgetMs ? s.overruns + 1 : 0;
  const over = overruns >= 2 || (overruns > 0 && (s.probing || frameMs > CLEAR_OVERRUN * choice.budgetMs));
  const budgetMs = over && here === 0 ? SLOW_BUDGET_MS : choice.budgetMs;
  const holds = frameMs <= HOLDS * budgetMs;
  // The best rung whose frame with one step is predicted within `limitMs`; its steps fill the budget.
  const pick = (candidates: readonly Rung[], limitMs: number): BudgetChoice | undefined => {
    const rung = candidates.find((r) => predictedFrameMs(measured, r, 1, limits) <= limitMs);
    return rung && { ...rung, stepsPerFrame: stepsAt(measured, rung, budgetMs, limits, false), budgetMs };
  };
  let next: BudgetChoice | undefined;
  let banned = measured.banned;
  if (over) {
    // Too slow for its budget (the slow one, or the fast one below full quality): banned with every rung above it.
    if (budgetMs === choice.budgetMs) banned = [...banned, ...rungs.slice(0, here + 1).map(key)];
    // Down: neither the grid nor the pixel ratio goes up.
    const allowed = rungs.filter((r) => !banned.includes(key(r)) && r.gridN <= choice.gridN && r.pixelRatio <= choice.pixelRatio);
    const lowest = allowed.at(-1) ?? rungs.at(-1)!;
    // The rung risen to overran: back to the one it rose from, which held.
    const back = s.rose?.to === key(choice) ? s.rose.from : undefined;
    next = back ?? pick(allowed, budgetMs) ?? { ...lowest, stepsPerFrame: stepsAt(measured, lowest, budgetMs, limits, false), budgetMs };
  } else if (measured.probing) {
    // The first window held: the steps this rung affords.
    next = { ...choice, stepsPerFrame: stepsAt(measured, choice, budgetMs, limits, holds), budgetMs };
  } else if (w.ms >= UP_WINDOW_MS && holds && !measured.rose) {
    // Up: neither the grid nor the pixel ratio goes down.
    const above = rungs
      .slice(0, here)
      .filter((r) => !banned.includes(key(r)) && r.gridN >= choice.gridN && r.pixelRatio >= choice.pixelRatio);
    next = pick(above, UP_MARGIN * budgetMs);
  }
  const rose = measured.rose ?? (next && rungIndex(rungs, next) < here ? { from: choice, to: key(next) } : null);
  // A window judged in full (an overrun, the first one, or one as long as going up needs) starts anew.
  const judged = next !== undefined || w.ms >= UP_WINDOW_MS || overruns > 0;
  const after = { ...measured, banned, probing: false, overruns: over ? 0 : overruns };
  if (!next || !changed(next, choice)) return { ...after, window: judged ? EMPTY_WINDOW : w };
  return { ...after, choice: next, rose, window: EMPTY_WINDOW };
}

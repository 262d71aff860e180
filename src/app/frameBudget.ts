/**
 * The frame budget's decision (docs/governor.md): from what the animating frames cost, the flow's
 * grid, its steps per frame and the drawing buffer's pixel ratio, within the budget. A pure function
 * of the timings it is fed and its previous state; FrameGovernor measures and applies.
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

/**
 * A window is judged once it holds this many frames and lasts this long (ms) at the 60 Hz budget,
 * SLOW_WINDOW_MS at the slow one (a few frames, so that one late frame, a busy moment of the machine,
 * is not an overrun); the first frames at full quality are judged once they last two slow budgets,
 * however few (one such frame says the machine cannot hold 60 fps).
 */
const MIN_FRAMES = 2;
const MIN_WINDOW_MS = 500;
const SLOW_WINDOW_MS = 1000;
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
 * Under the 60 Hz budget the steps real time asks for may take this share of it. A frame held at
 * vsync shows no headroom, so the draw's own part is not known there without a GPU timer: a rung
 * whose draw and steps do not fit overruns, and the governor goes back.
 */
const FAST_SIM_SHARE = 0.5;
/**
 * The choice goes up only to a rung (or to more steps) predicted within this share of the budget,
 * after a window this long (ms), and only in the first window judged after the start's decision: a
 * later rise would follow the noise and the warming up of the costs measured, not the machine.
 */
const UP_MARGIN = 0.6;
const UP_WINDOW_MS = 1000;
/**
 * The share of a measured cost taken as fixed when carried to another grid or pixel ratio: a cost
 * per draw (a CPU rasteriser's, or a GPU's per pass) that the target's size does not change. A
 * second grid measured replaces it with the fit.
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
  /** The budget chosen (ms): FAST_BUDGET_MS, or DRAW_SHARE times the bubble's own frame within FAST_BUDGET_MS–SLOW_BUDGET_MS. */
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
  /** Whether a window may still go up: until the first one judged after the start's decision. */
  readonly mayRise: boolean;
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

/**
 * The first choice: START_GRID (the grid given, or the smallest if none is as small) at the
 * largest pixel ratio, one step a frame until frames are measured, the 60 Hz budget.
 */
export function initialBudget(limits: BudgetLimits): BudgetState {
  const gridN = Math.max(...limits.grids.filter((n) => n <= START_GRID), Math.min(...limits.grids));
  return {
    choice: { gridN, pixelRatio: Math.max(...limits.pixelRatios), stepsPerFrame: limits.fixedStepsPerFrame ?? 1, budgetMs: FAST_BUDGET_MS },
    banned: [],
    window: EMPTY_WINDOW,
    stepMs: {},
    drawMs: {},
    probing: true,
    rose: null,
    mayRise: true,
    overruns: 0,
  };
}

/** A cost measured at `at` (the nearest measured), carried to `x` by cells or pixels (x²), FIXED_SHARE of it fixed. */
function carried(measured: Costs, x: number): number | undefined {
  const known = Object.keys(measured).map(Number);
  if (known.length === 0) return undefined;
  const at = known.reduce((a, b) => (Math.abs(b - x) < Math.abs(a - x) || (Math.abs(b - x) === Math.abs(a - x) && b > a) ? b : a));
  return meanOf(measured, at) * (FIXED_SHARE + (1 - FIXED_SHARE) * (x / at) ** 2);
}

/**
 * A step's cost at a grid (docs/flow.md's cost model: a + b·N², a fixed cost per pass and one per
 * cell): measured; with two grids measured, the fit through the nearest two (below and above, or
 * the two nearest on its side); with one, carried.
 */
function predictedStepMs(stepMs: Costs, gridN: number): number | undefined {
  if (stepMs[gridN] !== undefined) return meanOf(stepMs, gridN);
  const known = Object.keys(stepMs)
    .map(Number)
    .sort((a, b) => a - b);
  if (known.length < 2) return carried(stepMs, gridN);
  const above = known.findIndex((n) => n > gridN);
  const [n1, n2] = above === 0 ? [known[0]!, known[1]!] : above < 0 ? [known.at(-2)!, known.at(-1)!] : [known[above - 1]!, known[above]!];
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

/** The steps real time asks of a frame of `frameMs` at a grid (n·Δt ≥ the frame), at least one. */
const realTimeSteps = (limits: BudgetLimits, gridN: number, frameMs: number): number =>
  Math.min(limits.maxStepsPerFrame, Math.max(1, Math.ceil((frameMs * limits.simSpeed) / (1000 * limits.stepSeconds(gridN)))));

/**
 * Whether a rung with `steps` steps a frame is predicted within `share` of the budget: under the
 * 60 Hz budget, its steps within FAST_SIM_SHARE of it; elsewhere its frame.
 */
function affords(s: BudgetState, rung: Rung, steps: number, budgetMs: number, share: number, limits: BudgetLimits): boolean {
  if (budgetMs > FAST_BUDGET_MS) return predictedFrameMs(s, rung, steps, limits) <= share * budgetMs;
  const step = predictedStepMs(s.stepMs, rung.gridN) ?? 0;
  return step * limits.views * steps <= share * FAST_SIM_SHARE * budgetMs;
}

/** Whether a rung is predicted within `share` of the budget: under the 60 Hz budget with the steps real time asks for, elsewhere with one step. */
const fits = (s: BudgetState, rung: Rung, budgetMs: number, share: number, limits: BudgetLimits): boolean =>
  affords(s, rung, budgetMs > FAST_BUDGET_MS ? 1 : realTimeSteps(limits, rung.gridN, budgetMs), budgetMs, share, limits);

/** The budget where the 60 Hz one is overrun: DRAW_SHARE times the bubble's own frame at the largest pixel ratio, within FAST_BUDGET_MS–SLOW_BUDGET_MS. */
function slowBudgetMs(s: BudgetState, limits: BudgetLimits): number {
  const draw = carried(s.drawMs, Math.max(...limits.pixelRatios)) ?? SLOW_BUDGET_MS;
  return Math.min(SLOW_BUDGET_MS, Math.max(FAST_BUDGET_MS, DRAW_SHARE * draw));
}

const rungIndex = (rungs: readonly Rung[], x: Rung): number => rungs.findIndex((r) => r.gridN === x.gridN && r.pixelRatio === x.pixelRatio);

const changed = (a: BudgetChoice, b: BudgetChoice): boolean =>
  a.gridN !== b.gridN || a.pixelRatio !== b.pixelRatio || a.stepsPerFrame !== b.stepsPerFrame || a.budgetMs !== b.budgetMs;

/**
 * The governor's next state after a frame (docs/governor.md). Frames gather into a window; once it
 * holds MIN_FRAMES frames over MIN_WINDOW_MS it is judged by its mean, and its costs join those
 * measured before. The first window judged decides from the costs at the start: one over the
 * 60 Hz budget takes the slow budget (slowBudgetMs) and the best rung of the whole ladder predicted
 * within it; one that holds goes up to the best rung whose steps are predicted within it. Later, an
 * overrun (above OVERRUN budgets) bans the rung with every rung above it and goes down to the best
 * rung left predicted within the budget (the lowest if none is); the first window judged after the
 * start's decision, held for UP_WINDOW_MS, goes up to a rung not banned predicted within UP_MARGIN
 * of the budget; no window after it goes up.
 * The steps fill what the draw leaves of the budget, no more than real time asks.
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
  const windowMs = state.choice.budgetMs > FAST_BUDGET_MS ? SLOW_WINDOW_MS : MIN_WINDOW_MS;
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
  // The start overran the 60 Hz budget: the machine cannot hold it, and the slow budget is taken for good.
  const leavesFast = over && s.probing && choice.budgetMs === FAST_BUDGET_MS;
  const budgetMs = leavesFast ? slowBudgetMs(measured, limits) : choice.budgetMs;
  const fast = budgetMs === FAST_BUDGET_MS;
  const holds = frameMs <= HOLDS * budgetMs;
  // A rung with the steps it takes; the best rung predicted within `share` of the budget (under the 60 Hz budget it is expected to hold).
  const withSteps = (rung: Rung, holdsThere: boolean): BudgetChoice => ({
    ...rung,
    stepsPerFrame: stepsAt(measured, rung, budgetMs, limits, holdsThere),
    budgetMs,
  });
  const pick = (candidates: readonly Rung[], share: number): BudgetChoice | undefined => {
    const rung = candidates.find((r) => fits(measured, r, budgetMs, share, limits));
    return rung && withSteps(rung, fast);
  };
  const notBelow = (r: Rung) => r.gridN >= choice.gridN && r.pixelRatio >= choice.pixelRatio;
  let next: BudgetChoice | undefined;
  let banned = measured.banned;
  if (leavesFast) {
    // Up or down the whole ladder, as the costs at the start predict.
    next = pick(rungs, 1) ?? withSteps(rungs.at(-1)!, false);
  } else if (over) {
    // Too slow for its budget: banned with every rung above it.
    banned = [...banned, ...rungs.slice(0, here + 1).map(key)];
    // Down: neither the grid nor the pixel ratio goes up.
    const allowed = rungs.filter((r) => !banned.includes(key(r)) && r.gridN <= choice.gridN && r.pixelRatio <= choice.pixelRatio);
    // The rung risen to overran: back to the one it rose from, which held.
    const back = s.rose?.to === key(choice) ? s.rose.from : undefined;
    next = back ?? pick(allowed, 1) ?? withSteps(allowed.at(-1) ?? rungs.at(-1)!, false);
  } else if (measured.probing) {
    // The start held the 60 Hz budget: up to the best rung predicted within it, else the steps the start affords.
    next = pick(rungs.slice(0, here).filter(notBelow), 1) ?? withSteps(choice, holds);
  } else if (w.ms >= UP_WINDOW_MS && holds && measured.mayRise) {
    // Up: neither the grid nor the pixel ratio goes down; else more steps here, if the frames measured afford them.
    const above = pick(
      rungs.slice(0, here).filter((r) => !banned.includes(key(r)) && notBelow(r)),
      UP_MARGIN,
    );
    const more = withSteps(choice, fast);
    const affordsMore =
      more.stepsPerFrame > choice.stepsPerFrame && affords(measured, choice, more.stepsPerFrame, budgetMs, UP_MARGIN, limits);
    next = above ?? (affordsMore ? more : undefined);
  }
  // A move up after the start's decision (to a finer rung, or more steps) is the governor's one rise.
  const up = next !== undefined && !s.probing && (rungIndex(rungs, next) < here || next.stepsPerFrame > choice.stepsPerFrame);
  const rose = measured.rose ?? (up ? { from: choice, to: key(next!) } : null);
  // A window judged in full (an overrun, the first one, or one as long as going up needs) starts anew.
  const judged = next !== undefined || w.ms >= UP_WINDOW_MS || overruns > 0;
  const after = { ...measured, banned, probing: false, mayRise: s.probing || (measured.mayRise && !judged), overruns: over ? 0 : overruns };
  if (!next || !changed(next, choice)) return { ...after, window: judged ? EMPTY_WINDOW : w };
  return { ...after, choice: next, rose, window: EMPTY_WINDOW };
}

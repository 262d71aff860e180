/**
 * The frame budget's decision (docs/governor.md): from what the animating frames cost, the flow's
 * grid, its steps per frame and the drawing buffer's pixel ratio, within the budget. A pure function
 * of the timings it is fed and its previous state; FrameGovernor measures and applies. Its terms:
 * budgetTerms.ts; what a rung is predicted to cost: budgetPrediction.ts.
 */
import {
  type BudgetChoice,
  type BudgetLimits,
  type BudgetState,
  FAST_BUDGET_MS,
  type FrameSample,
  type Rung,
  SLOW_BUDGET_MS,
  START_GRID,
  added,
} from './budgetTerms.ts';
import { affords, fits, slowBudgetMs, stepsAt } from './budgetPrediction.ts';

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
/**
 * The choice goes up only to a rung (or to more steps) predicted within this share of the budget,
 * after a window this long (ms), and only in the first window judged after the start's decision: a
 * later rise would follow the noise and the warming up of the costs measured, not the machine.
 */
const UP_MARGIN = 0.6;
const UP_WINDOW_MS = 1000;
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

const rungIndex = (rungs: readonly Rung[], x: Rung): number => rungs.findIndex((r) => r.gridN === x.gridN && r.pixelRatio === x.pixelRatio);

const changed = (a: BudgetChoice, b: BudgetChoice): boolean =>
  a.gridN !== b.gridN || a.pixelRatio !== b.pixelRatio || a.stepsPerFrame !== b.stepsPerFrame || a.budgetMs !== b.budgetMs;

/** The window with one frame more: its count, ms, simulation ms and steps, and the GPU's draw ms while every frame of it has them. */
const gathered = (w: BudgetState['window'], sample: FrameSample): BudgetState['window'] => ({
  frames: w.frames + 1,
  ms: w.ms + sample.intervalMs,
  simMs: w.simMs + sample.simMs,
  steps: w.steps + sample.steps,
  drawMs: w.drawMs === null || sample.drawMs === undefined ? null : w.drawMs + sample.drawMs,
});

/** Whether a window is judged: MIN_FRAMES over MIN_WINDOW_MS (SLOW_WINDOW_MS at the slow budget); the first frames once they last two slow budgets. */
function ready(s: BudgetState): boolean {
  const w = s.window;
  const windowMs = s.choice.budgetMs > FAST_BUDGET_MS ? SLOW_WINDOW_MS : MIN_WINDOW_MS;
  if (s.probing) return w.ms >= 2 * SLOW_BUDGET_MS || (w.frames >= MIN_FRAMES && w.ms >= MIN_WINDOW_MS);
  return w.frames >= MIN_FRAMES && w.ms >= windowMs;
}

/** A window judged: the state with its costs joined to those measured, the ladder and the choice's rung on it, and its mean frame against the budget. */
interface Verdict {
  readonly measured: BudgetState;
  readonly rungs: readonly Rung[];
  readonly here: number;
  readonly overruns: number;
  readonly over: boolean;
  /** The start overran the 60 Hz budget: the machine cannot hold it, and the slow budget is taken for good. */
  readonly leavesFast: boolean;
  readonly budgetMs: number;
  readonly holds: boolean;
}

function judged(s: BudgetState, limits: BudgetLimits): Verdict {
  const { choice, window: w } = s;
  const frameMs = w.ms / w.frames;
  const measured: BudgetState = {
    ...s,
    stepMs: added(s.stepMs, choice.gridN, w.simMs, w.steps),
    drawMs: added(s.drawMs, choice.pixelRatio, w.drawMs ?? Math.max(0, w.ms - w.simMs), w.frames),
  };
  const rungs = ladder(limits);
  const overruns = frameMs > OVERRUN * choice.budgetMs ? s.overruns + 1 : 0;
  const over = overruns >= 2 || (overruns > 0 && (s.probing || frameMs > CLEAR_OVERRUN * choice.budgetMs));
  const leavesFast = over && s.probing && choice.budgetMs === FAST_BUDGET_MS;
  const budgetMs = leavesFast ? slowBudgetMs(measured, limits) : choice.budgetMs;
  // A choice off the ladder (limits changed under it) counts as its top.
  const here = Math.max(0, rungIndex(rungs, choice));
  return { measured, rungs, here, overruns, over, leavesFast, budgetMs, holds: frameMs <= HOLDS * budgetMs };
}

/** The choice a judged window moves to (undefined: it stays where it is), and the rungs banned with it. */
function nextChoice(v: Verdict, limits: BudgetLimits): { readonly next: BudgetChoice | undefined; readonly banned: readonly string[] } {
  const { measured, rungs, here, budgetMs, holds } = v;
  const { choice } = measured;
  const fast = budgetMs === FAST_BUDGET_MS;
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
  const banned = measured.banned;
  // Up or down the whole ladder, as the costs at the start predict.
  if (v.leavesFast) return { next: pick(rungs, 1) ?? withSteps(rungs.at(-1)!, false), banned };
  if (v.over) {
    // Too slow for its budget: banned with every rung above it; down, neither the grid nor the pixel ratio going up.
    const more = [...banned, ...rungs.slice(0, here + 1).map(key)];
    const allowed = rungs.filter((r) => !more.includes(key(r)) && r.gridN <= choice.gridN && r.pixelRatio <= choice.pixelRatio);
    // The rung risen to overran: back to the one it rose from, which held.
    const back = measured.rose?.to === key(choice) ? measured.rose.from : undefined;
    return { next: back ?? pick(allowed, 1) ?? withSteps(allowed.at(-1) ?? rungs.at(-1)!, false), banned: more };
  }
  // The start held the 60 Hz budget: up to the best rung predicted within it, else the steps the start affords.
  if (measured.probing) return { next: pick(rungs.slice(0, here).filter(notBelow), 1) ?? withSteps(choice, holds), banned };
  if (!(measured.window.ms >= UP_WINDOW_MS && holds && measured.mayRise)) return { next: undefined, banned };
  // Up: neither the grid nor the pixel ratio goes down; else more steps here, if the frames measured afford them.
  const above = pick(
    rungs.slice(0, here).filter((r) => !banned.includes(key(r)) && notBelow(r)),
    UP_MARGIN,
  );
  const more = withSteps(choice, fast);
  const affordsMore =
    more.stepsPerFrame > choice.stepsPerFrame && affords(measured, choice, more.stepsPerFrame, budgetMs, UP_MARGIN, limits);
  return { next: above ?? (affordsMore ? more : undefined), banned };
}

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
  const s: BudgetState = { ...state, window: gathered(state.window, sample) };
  if (!ready(s)) return s;
  const verdict = judged(s, limits);
  const { measured, rungs, here, overruns, over } = verdict;
  const { choice, window: w } = s;
  const { next, banned } = nextChoice(verdict, limits);
  // A move up after the start's decision (to a finer rung, or more steps) is the governor's one rise.
  const up = next !== undefined && !s.probing && (rungIndex(rungs, next) < here || next.stepsPerFrame > choice.stepsPerFrame);
  const rose = measured.rose ?? (up ? { from: choice, to: key(next) } : null);
  // A window judged in full (an overrun, the first one, or one as long as going up needs) starts anew.
  const judgedInFull = next !== undefined || w.ms >= UP_WINDOW_MS || overruns > 0;
  const after = {
    ...measured,
    banned,
    probing: false,
    mayRise: s.probing || (measured.mayRise && !judgedInFull),
    overruns: over ? 0 : overruns,
  };
  if (!next || !changed(next, choice)) return { ...after, window: judgedInFull ? EMPTY_WINDOW : w };
  return { ...after, choice: next, rose, window: EMPTY_WINDOW };
}

import {
  type BudgetLimits,
  type BudgetState,
  type Costs,
  DRAW_SHARE,
  FAST_BUDGET_MS,
  GOVERNED_MAX_STEPS,
  type Rung,
  SLOW_BUDGET_MS,
  meanOf,
} from './budgetTerms.ts';

/**
 * What a rung of the frame budget's ladder is predicted to cost (docs/governor.md#the-decision): a
 * step at a grid and the bubble's draw at a pixel ratio, from the costs measured at others, and the
 * steps a frame affords there.
 */

/** The steps fill this share of the budget (less the draw): a frame planned at 0.8 budgets overruns only 1.5 times as long. */
const STEP_FILL = 0.8;
/**
 * Under the 60 Hz budget the steps real time asks for may take this share of it. A frame held at
 * vsync shows no headroom, so the draw's own part is not known there without a GPU timer: a rung
 * whose draw and steps do not fit overruns, and the governor goes back.
 */
const FAST_SIM_SHARE = 0.5;
/**
 * The share of a measured cost taken as fixed when carried to another grid or pixel ratio: a cost
 * per draw (a CPU rasteriser's, or a GPU's per pass) that the target's size does not change. A
 * second grid measured replaces it with the fit.
 */
const FIXED_SHARE = 0.5;

/** A cost measured at `at` (the nearest measured), carried to `x` by cells or pixels (x²), FIXED_SHARE of it fixed. */
export function carried(measured: Costs, x: number): number | undefined {
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
export function predictedStepMs(stepMs: Costs, gridN: number): number | undefined {
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
export function stepsAt(s: BudgetState, rung: Rung, budgetMs: number, limits: BudgetLimits, holds: boolean): number {
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
export function predictedFrameMs(s: BudgetState, rung: Rung, steps: number, limits: BudgetLimits): number {
  const step = predictedStepMs(s.stepMs, rung.gridN) ?? 0;
  const draw = carried(s.drawMs, rung.pixelRatio) ?? 0;
  return draw + Math.min(steps, GOVERNED_MAX_STEPS) * step * limits.views;
}

/** The steps real time asks of a frame of `frameMs` at a grid (n·Δt ≥ the frame), at least one. */
export const realTimeSteps = (limits: BudgetLimits, gridN: number, frameMs: number): number =>
  Math.min(limits.maxStepsPerFrame, Math.max(1, Math.ceil((frameMs * limits.simSpeed) / (1000 * limits.stepSeconds(gridN)))));

/**
 * Whether a rung with `steps` steps a frame is predicted within `share` of the budget: under the
 * 60 Hz budget, its steps within FAST_SIM_SHARE of it; elsewhere its frame.
 */
export function affords(s: BudgetState, rung: Rung, steps: number, budgetMs: number, share: number, limits: BudgetLimits): boolean {
  if (budgetMs > FAST_BUDGET_MS) return predictedFrameMs(s, rung, steps, limits) <= share * budgetMs;
  const step = predictedStepMs(s.stepMs, rung.gridN) ?? 0;
  return step * limits.views * steps <= share * FAST_SIM_SHARE * budgetMs;
}

/** Whether a rung is predicted within `share` of the budget: under the 60 Hz budget with the steps real time asks for, elsewhere with one step. */
export const fits = (s: BudgetState, rung: Rung, budgetMs: number, share: number, limits: BudgetLimits): boolean =>
  affords(s, rung, budgetMs > FAST_BUDGET_MS ? 1 : realTimeSteps(limits, rung.gridN, budgetMs), budgetMs, share, limits);

/** The budget where the 60 Hz one is overrun: DRAW_SHARE times the bubble's own frame at the largest pixel ratio, within FAST_BUDGET_MS–SLOW_BUDGET_MS. */
export function slowBudgetMs(s: BudgetState, limits: BudgetLimits): number {
  const draw = carried(s.drawMs, Math.max(...limits.pixelRatios)) ?? SLOW_BUDGET_MS;
  return Math.min(SLOW_BUDGET_MS, Math.max(FAST_BUDGET_MS, DRAW_SHARE * draw));
}

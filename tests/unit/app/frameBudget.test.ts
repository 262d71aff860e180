import { describe, expect, it } from 'vitest';
import {
  type BudgetChoice,
  type BudgetLimits,
  FAST_BUDGET_MS,
  GOVERNED_GRID,
  GOVERNED_GRIDS,
  GOVERNED_MAX_STEPS,
  governedPixelRatios,
  SLOW_BUDGET_MS,
} from '../../../src/app/budgetTerms.ts';
import { initialBudget, ladder, nextBudget } from '../../../src/app/frameBudget.ts';
import { shownPixelRatio } from '../../../src/settings/pixelRatio.ts';
import { mulberry32 } from '../../seededRandom.ts';
import { GOVERNED_FRAME_RATIO, GOVERNOR_NOISE } from '../../tolerances.ts';

/**
 * A machine the governor is fed timings of, its costs written independently of the governor's
 * model: a frame is the bubble's draw (a fixed part and a part per pixel) and the steps (a fixed
 * cost per pass and a cost per cell, 6N² cells), no shorter than the display's vsync.
 */
interface Machine {
  readonly vsyncMs: number;
  readonly drawFixedMs: number;
  /** ms per unit of pixel ratio² (the drawing buffer's pixels). */
  readonly drawPixelMs: number;
  /** ms per pass (PASSES a step) and per cell per step. */
  readonly passMs: number;
  readonly cellMs: number;
  /** The device's pixel ratio. */
  readonly dpr: number;
}

/** Draws a step at the flow's defaults (docs/flow.md#what-a-step-costs), at every grid: the surfactant solve's sweeps are most of them. */
const PASSES = 103;
/** The ladder's grids up to full quality's, N = 128 (the flow's default). */
const LADDER = GOVERNED_GRIDS.filter((n) => n <= 128);
/** 60 Hz, a real GPU: a step at N = 128 ≈ 0.45 ms, the draw a few ms. */
const GPU: Machine = { vsyncMs: FAST_BUDGET_MS, drawFixedMs: 1, drawPixelMs: 1.5, passMs: 0.002, cellMs: 2.5e-6, dpr: 2 };
/** SwiftShader at 1280×720, pixel ratio 1, as measured on a 2-core machine: the bubble's frame 93 ms, a step 79 ms at N = 32 and 283 ms at 64. */
const SWIFTSHADER: Machine = { vsyncMs: 0, drawFixedMs: 20, drawPixelMs: 73, passMs: 0.107, cellMs: 0.0111, dpr: 1 };
/** llvmpipe at 1280×720, pixel ratio 1, as measured there: the bubble's frame 54 ms (most of it the page's compositing), a step 20 ms at N = 16 and 91 ms at 48. */
const LLVMPIPE: Machine = { vsyncMs: 0, drawFixedMs: 14, drawPixelMs: 40, passMs: 0.107, cellMs: 0.0058, dpr: 1 };
/** An integrated GPU at pixel ratio 2 whose bubble alone cannot hold 60 fps (28 ms a frame). */
const LAPTOP: Machine = { vsyncMs: FAST_BUDGET_MS, drawFixedMs: 4, drawPixelMs: 6, passMs: 0.02, cellMs: 2e-5, dpr: 2 };

const stepMsOf = (m: Machine, n: number) => PASSES * m.passMs + 6 * n * n * m.cellMs;
/** The bubble's own frame at the device's pixel ratio (a painted field's frame, without a film to simulate). */
const ownFrameMs = (m: Machine) => Math.max(m.vsyncMs, m.drawFixedMs + m.drawPixelMs * m.dpr ** 2);

function limitsFor(m: Machine, over: Partial<BudgetLimits> = {}): BudgetLimits {
  return {
    grids: LADDER,
    pixelRatios: governedPixelRatios(shownPixelRatio(m.dpr)),
    maxStepsPerFrame: GOVERNED_MAX_STEPS,
    baseStepsPerFrame: 8,
    fixedStepsPerFrame: null,
    // The flow's step shrinks with the cell (an advective Courant bound): 3.98 ms at N = 128.
    stepSeconds: (n) => (3.98e-3 * 128) / n,
    simSpeed: 1,
    views: 1,
    ...over,
  };
}

interface Run {
  /** Every choice with the simulated time (ms from the first frame) it was made at. */
  readonly choices: readonly { readonly atMs: number; readonly choice: BudgetChoice }[];
  /** The frames' simulated intervals after the last change. */
  readonly settledFrames: readonly number[];
}

/**
 * Feeds the governor `seconds` of simulated frames of machine `m`, each cost times 1 ± `noise`
 * (seeded) and times `slowness` at the frame's time (ms from the first frame).
 */
function run(m: Machine, limits: BudgetLimits, seconds: number, noise = 0, seed = 1, slowness = (_tMs: number) => 1): Run {
  const random = mulberry32(seed);
  let t = 0;
  const jitter = () => (1 + noise * (2 * random() - 1)) * slowness(t);
  let state = initialBudget(limits);
  const choices = [{ atMs: 0, choice: state.choice }];
  let settledFrames: number[] = [];
  while (t < seconds * 1000) {
    const { gridN, pixelRatio, stepsPerFrame } = state.choice;
    const steps = Math.min(stepsPerFrame, GOVERNED_MAX_STEPS) * limits.views;
    const simMs = steps * stepMsOf(m, gridN) * jitter();
    const drawMs = (m.drawFixedMs + m.drawPixelMs * pixelRatio ** 2) * jitter();
    const intervalMs = Math.max(m.vsyncMs, drawMs + simMs);
    t += intervalMs;
    settledFrames.push(intervalMs);
    const next = nextBudget(state, { intervalMs, simMs, steps }, limits);
    if (next.choice !== state.choice) {
      choices.push({ atMs: t, choice: next.choice });
      settledFrames = [];
    }
    state = next;
  }
  return { choices, settledFrames };
}

const mean = (xs: readonly number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
const last = (r: Run) => r.choices.at(-1)!.choice;
const SEEDS = Array.from({ length: 20 }, (_, i) => i + 1);
const MACHINES = { GPU, SWIFTSHADER, LLVMPIPE, LAPTOP };
/** The machines whose bubble alone cannot hold 60 Hz. */
const SLOW_MACHINES = { SWIFTSHADER, LLVMPIPE, LAPTOP };

describe('the frame budget (fed timings)', () => {
  it('orders the ladder from full quality down, a halved grid side counting as a halved pixel ratio', () => {
    const rungs = ladder({ grids: [32, 64, 128], pixelRatios: [1, 2] });
    expect(rungs[0]).toEqual({ gridN: 128, pixelRatio: 2 });
    expect(rungs.at(-1)).toEqual({ gridN: 32, pixelRatio: 1 });
    // 128@1 and 64@2 keep as much; the finer grid comes first.
    expect(rungs.slice(1, 3)).toEqual([
      { gridN: 128, pixelRatio: 1 },
      { gridN: 64, pixelRatio: 2 },
    ]);
  });

  it('keeps full quality and the 60 Hz budget on a machine that holds it', () => {
    const r = run(GPU, limitsFor(GPU), 30);
    expect(last(r)).toMatchObject({ gridN: 128, pixelRatio: 2, budgetMs: FAST_BUDGET_MS });
    // More than the first frames' one step, as many as real time asks (0.3 ms of film a step at N = 128 → 16.7/(0.17·…)).
    expect(last(r).stepsPerFrame).toBeGreaterThan(1);
  });

  for (const [name, m] of Object.entries(SLOW_MACHINES)) {
    it(`${name}: where the bubble alone cannot hold 60 Hz, the flowing film’s frames stay within ${GOVERNED_FRAME_RATIO} times the bubble’s own, film time running`, () => {
      for (const seed of SEEDS) {
        const r = run(m, limitsFor(m), 30, GOVERNOR_NOISE, seed);
        const c = last(r);
        expect(c.budgetMs, `seed ${seed}`).toBeGreaterThan(FAST_BUDGET_MS);
        expect(mean(r.settledFrames), `seed ${seed}`).toBeLessThanOrEqual(GOVERNED_FRAME_RATIO * ownFrameMs(m));
        expect(c.stepsPerFrame).toBeGreaterThanOrEqual(1);
      }
    });
  }

  it('lowers quality only as far as needed: a laptop whose draw leaves room keeps a finer grid and more pixels than a CPU rasteriser', () => {
    const laptop = last(run(LAPTOP, limitsFor(LAPTOP), 30));
    const cpu = last(run(SWIFTSHADER, limitsFor(SWIFTSHADER), 30));
    expect(laptop.gridN).toBeGreaterThan(cpu.gridN);
    expect(laptop.pixelRatio).toBeGreaterThan(cpu.pixelRatio);
  });

  for (const [name, m] of Object.entries(MACHINES)) {
    it(`${name}: settles within 3 s and changes at most twice in 30 s of noisy timings, never going back to a rung found too slow nor trading one knob for the other`, () => {
      for (const seed of SEEDS) {
        const r = run(m, limitsFor(m), 30, GOVERNOR_NOISE, seed);
        const changes = r.choices.slice(1);
        expect(changes.length, `seed ${seed}`).toBeLessThanOrEqual(2);
        expect(changes.at(-1)?.atMs ?? 0, `seed ${seed}`).toBeLessThanOrEqual(3000);
        // A rung left for a lower one (found too slow) is never taken again.
        const rungs = r.choices.map(({ choice }) => `${choice.gridN}@${choice.pixelRatio}`);
        const trail = `seed ${seed}: ${rungs.join(' → ')}`;
        r.choices.forEach(({ choice }, i) => {
          const next = r.choices[i + 1]?.choice;
          if (next && next.gridN * next.pixelRatio < choice.gridN * choice.pixelRatio)
            expect(rungs.slice(i + 1), trail).not.toContain(rungs[i]);
        });
        // After the start's decision (a place on the whole ladder), a move never trades one knob for the other: both go down, or both go up.
        for (const [{ choice: a }, { choice: b }] of r.choices.slice(2).map((c, i) => [r.choices[i + 1]!, c] as const)) {
          const down = b.gridN <= a.gridN && b.pixelRatio <= a.pixelRatio;
          const up = b.gridN >= a.gridN && b.pixelRatio >= a.pixelRatio;
          expect(down || up, `seed ${seed}: ${a.gridN}@${a.pixelRatio} → ${b.gridN}@${b.pixelRatio}`).toBe(true);
        }
      }
    });
  }

  for (const [name, m] of Object.entries(SLOW_MACHINES)) {
    it(`${name}: a page warming up (its first frames twice as slow, as fast as the machine by 10 s) settles within 3 s all the same`, () => {
      const warmingUp = (tMs: number) => 1 + Math.max(0, 1 - tMs / 10_000);
      for (const seed of SEEDS) {
        const r = run(m, limitsFor(m), 30, GOVERNOR_NOISE, seed, warmingUp);
        const trail = `seed ${seed}: ${r.choices.map(({ atMs, choice }) => `${choice.gridN}@${choice.pixelRatio}×${choice.stepsPerFrame} at ${atMs.toFixed(0)} ms`).join(' → ')}`;
        expect(r.choices.length - 1, trail).toBeLessThanOrEqual(2);
        expect(r.choices.at(-1)!.atMs, trail).toBeLessThanOrEqual(3000);
      }
    });
  }

  it('gives one step a frame where no step has been measured (the first frames’ film time asked for none)', () => {
    const limits = limitsFor(SWIFTSHADER);
    let state = initialBudget(limits);
    // Two slow frames at full quality without steps: too slow for 60 Hz, and nothing known of a step.
    for (let i = 0; i < 2; i++) state = nextBudget(state, { intervalMs: 600, simMs: 0, steps: 0 }, limits);
    // The bubble's own frame of 600 ms: the slow budget at its most.
    expect(state.choice.budgetMs).toBe(SLOW_BUDGET_MS);
    expect(state.choice.stepsPerFrame).toBe(1);
  });

  it('three bubbles share one budget: each takes fewer steps, and the frames stay within it', () => {
    const one = last(run(LAPTOP, limitsFor(LAPTOP), 30));
    const r = run(LAPTOP, limitsFor(LAPTOP, { views: 3 }), 30);
    expect(mean(r.settledFrames)).toBeLessThanOrEqual(GOVERNED_FRAME_RATIO * ownFrameMs(LAPTOP));
    expect(last(r).gridN * last(r).stepsPerFrame).toBeLessThanOrEqual(one.gridN * one.stepsPerFrame);
  });

  it('never leaves its ranges, on machines of any speed', () => {
    const random = mulberry32(7);
    for (let i = 0; i < 40; i++) {
      const scale = 10 ** (4 * random() - 2);
      const m: Machine = {
        vsyncMs: random() < 0.5 ? FAST_BUDGET_MS : 0,
        drawFixedMs: scale * 10 * random(),
        drawPixelMs: scale * 50 * random(),
        passMs: scale * random(),
        cellMs: scale * 1e-3 * random(),
        dpr: [1, 1.5, 2, 3][i % 4]!,
      };
      // The whole range of grids the governor may take, 16–256.
      const limits = limitsFor(m, { grids: [...GOVERNED_GRIDS] });
      for (const { choice } of run(m, limits, 20, GOVERNOR_NOISE, i).choices) {
        expect(limits.grids).toContain(choice.gridN);
        expect(choice.gridN).toBeGreaterThanOrEqual(GOVERNED_GRID.min);
        expect(choice.gridN).toBeLessThanOrEqual(GOVERNED_GRID.max);
        expect(limits.pixelRatios).toContain(choice.pixelRatio);
        expect(Number.isInteger(choice.stepsPerFrame)).toBe(true);
        expect(choice.stepsPerFrame).toBeGreaterThanOrEqual(1);
        expect(choice.stepsPerFrame).toBeLessThanOrEqual(GOVERNED_MAX_STEPS);
        expect(choice.budgetMs).toBeGreaterThanOrEqual(FAST_BUDGET_MS);
        expect(choice.budgetMs).toBeLessThanOrEqual(SLOW_BUDGET_MS);
      }
    }
  });

  it('honours a user’s grid, pixel ratio and steps exactly, however slow the frames', () => {
    const limits = limitsFor(SWIFTSHADER, { grids: [24], pixelRatios: [1.25], fixedStepsPerFrame: Infinity });
    const r = run(SWIFTSHADER, limits, 30, GOVERNOR_NOISE);
    for (const { choice } of r.choices) expect(choice).toMatchObject({ gridN: 24, pixelRatio: 1.25, stepsPerFrame: Infinity });
    const grid = run(SWIFTSHADER, limitsFor(SWIFTSHADER, { grids: [200] }), 30);
    for (const { choice } of grid.choices) expect(choice.gridN).toBe(200);
  });
});

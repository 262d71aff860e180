import { describe, expect, it } from 'vitest';
import type { BudgetChoice } from '../../../src/app/budgetTerms.ts';
import { FrameGovernor, type GovernedView } from '../../../src/app/frameGovernor.ts';

/** A document as the governor uses it: a key, and its visibility events. */
const fakeDocument = () => ({ addEventListener: () => {} }) as unknown as Document;

/** A flowing view leaving everything to the governor, recording the choices it is given. */
function flowingView(given: Partial<Pick<GovernedView, 'gridN' | 'pixelRatio' | 'simSpeedGiven'>> = {}) {
  const choices: BudgetChoice[] = [];
  const view: GovernedView = {
    gridN: undefined,
    pixelRatio: undefined,
    simSpeedGiven: false,
    flows: true,
    baseStepsPerFrame: 8,
    apply: (c) => choices.push(c),
    ...given,
  };
  return { view, choices };
}

/** Frames of `views` views at 60 Hz, each view's simulation 0.5 ms a step, for `seconds` (animation frames in step, one `now` each). */
function animate(governor: FrameGovernor, views: readonly GovernedView[], seconds: number, stepsOf: () => number): void {
  // A step of 0.01 ms of film for 0.5 ms of work: real time is out of reach, the budget bounds the steps.
  const grid = { gridN: 128, stepSeconds: 1e-5 };
  for (let now = 0; now < seconds * 1000; now += 1000 / 60) {
    for (let i = 0; i < views.length; i++)
      governor.drawn(now, { simMs: 0.5 * stepsOf(), drawMs: 2, steps: stepsOf(), settling: false }, grid, now > 0);
  }
}

describe('the frame governor of a page', () => {
  it('is one per document', () => {
    const doc = fakeDocument();
    expect(FrameGovernor.of(doc)).toBe(FrameGovernor.of(doc));
    expect(FrameGovernor.of(fakeDocument())).not.toBe(FrameGovernor.of(doc));
  });

  it('gives every view the same choice, and divides the steps of one budget among the flowing views', () => {
    const alone = FrameGovernor.of(fakeDocument());
    const one = flowingView();
    alone.join(one.view);
    animate(alone, [one.view], 2, () => alone.choice!.stepsPerFrame);

    const shared = FrameGovernor.of(fakeDocument());
    const [a, b] = [flowingView(), flowingView()];
    shared.join(a.view);
    shared.join(b.view);
    animate(shared, [a.view, b.view], 2, () => shared.choice!.stepsPerFrame);

    expect(a.choices.at(-1)).toEqual(b.choices.at(-1));
    expect(shared.choice!.stepsPerFrame).toBeLessThan(alone.choice!.stepsPerFrame);
    // Each step costs 0.5 ms and each draw 2 ms: the steps fill what the draws leave of 80 % of 16.7 ms, shared.
    expect(alone.choice!.stepsPerFrame).toBe(Math.floor((0.8 * (1000 / 60) - 2) / 0.5));
    expect(shared.choice!.stepsPerFrame).toBe(Math.floor((0.8 * (1000 / 60) - 2 * 2) / (2 * 0.5)));
  });

  it('does not measure a frame in which a film was shown before its simulation, made, or compiled its programs', () => {
    const governor = FrameGovernor.of(fakeDocument());
    const { view, choices } = flowingView();
    governor.join(view);
    const given = choices.length;
    const grid = { gridN: 32, stepSeconds: 1e-3 };
    // Two seconds of frames a second long, each settling: were they measured, the 60 Hz budget would be left at the first judged window.
    for (let now = 0; now < 2000; now += 1000) governor.drawn(now, { simMs: 900, drawMs: null, steps: 1, settling: true }, grid, now > 0);
    expect(choices).toHaveLength(given);
    // The same frames, measured: the budget is left.
    for (let now = 2000; now < 6000; now += 1000) governor.drawn(now, { simMs: 900, drawMs: null, steps: 1, settling: false }, grid, true);
    expect(governor.choice!.budgetMs).toBeGreaterThan(1000 / 60);
  });

  it('keeps to the grid and pixel ratio a user gave when every view gave them, and starts anew when a view leaves', () => {
    const governor = FrameGovernor.of(fakeDocument());
    const fixed = flowingView({ gridN: 24, pixelRatio: 1.25, simSpeedGiven: true });
    governor.join(fixed.view);
    animate(governor, [fixed.view], 3, () => 1);
    for (const c of fixed.choices) expect(c).toMatchObject({ gridN: 24, pixelRatio: 1.25 });
    const auto = flowingView();
    governor.join(auto.view);
    expect(auto.choices.at(-1)!.gridN).not.toBe(24);
    governor.leave(auto.view);
    governor.leave(fixed.view);
    expect(governor.choice).toBeNull();
  });
});

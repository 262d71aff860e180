/** The flow's speed figures: steps per second as the median of the timed batches, after the untimed steps, each batch synced. */
import { afterEach, describe, expect, it, vi } from 'vitest';
import { simulationSpeed, timedStepsPerSecond } from '../../../scripts/bench/flowSpeed.ts';

describe('flow simulation speed', () => {
  afterEach(() => {
    vi.restoreAllMocks();
  });

  it('times each batch to its sync, after the untimed steps, and takes the median of the batches’ rates', () => {
    let clockMs = 0;
    vi.spyOn(performance, 'now').mockImplementation(() => clockMs);
    // The untimed steps take 100 s (left out); the batches of 4 steps take 1 s, 4 s and 2 s, each ended by its sync.
    const batchMs = [100_000, 1000, 4000, 2000];
    const calls: string[] = [];
    const rate = timedStepsPerSecond(
      { grids: [64], warmUpSteps: 3, batchSteps: 4, batches: 3 },
      (count) => calls.push(`step ${count}`),
      () => {
        calls.push('sync');
        clockMs += batchMs.shift()!;
      },
    );
    expect(calls).toEqual(['step 3', 'sync', 'step 4', 'sync', 'step 4', 'sync', 'step 4', 'sync']);
    // Rates 4, 1 and 2 steps per second.
    expect(rate).toBe(2);
  });

  it('film seconds per wall second are the steps per second times Δt', () => {
    expect(simulationSpeed(128, 0.004, 250)).toEqual({ gridN: 128, stepSeconds: 0.004, stepsPerSecond: 250, filmSecondsPerSecond: 1 });
  });
});

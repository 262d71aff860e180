import { describe, expect, it } from 'vitest';
import { runAtOnce } from '../../../scripts/bench/runAtOnce.ts';

/** A task that records its start and end in `log`, with the lane it ran in, and yields between them. */
const task = (name: string, cost: number, log: string[]) => ({
  cost,
  run: async (lane: string) => {
    log.push(`${lane} starts ${name}`);
    await new Promise((resolve) => setTimeout(resolve, cost));
    log.push(`${lane} ends ${name}`);
  },
});

describe('the bench task pool', () => {
  it('runs the tasks one by one in their order in a single lane', async () => {
    const log: string[] = [];
    await runAtOnce([task('a', 1, log), task('b', 3, log)], ['lane']);
    expect(log).toEqual(['lane starts a', 'lane ends a', 'lane starts b', 'lane ends b']);
  });

  it('runs each task once, the costliest first, each lane one task at a time', async () => {
    const log: string[] = [];
    await runAtOnce([task('cheap', 1, log), task('costly', 20, log), task('middle', 5, log), task('also cheap', 1, log)], ['A', 'B']);
    expect(log.filter((l) => l.includes('starts')).slice(0, 2)).toEqual(['A starts costly', 'B starts middle']);
    expect(log.filter((l) => l.includes('starts')).length).toBe(4);
    for (const lane of ['A', 'B']) {
      const own = log.filter((l) => l.startsWith(lane));
      own.forEach((l, i) => expect(l.includes(i % 2 === 0 ? 'starts' : 'ends')).toBe(true));
    }
  });
});

import { describe, expect, it } from 'vitest';
import { secondsLeft } from '../../../scripts/bench/progress.ts';

describe('bench progress', () => {
  it('time left is the seconds per unit of cost so far times the cost left', () => {
    // 30 s for 3 units done: 10 s a unit; 4.5 units left.
    expect(
      secondsLeft(
        [
          { cost: 1, seconds: 10 },
          { cost: 2, seconds: 20 },
        ],
        4.5,
      ),
    ).toBe(45);
    expect(secondsLeft([{ cost: 1, seconds: 10 }], 0)).toBe(0);
  });

  it('says nothing before a stage is done', () => {
    expect(secondsLeft([], 10)).toBeNull();
  });
});

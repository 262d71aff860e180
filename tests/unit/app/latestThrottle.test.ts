import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { latestThrottle } from '../../../src/app/latestThrottle.ts';

describe('latestThrottle', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('says the first value at once, then at most one per interval, the last one winning', () => {
    const said: number[] = [];
    const t = latestThrottle((v: number) => said.push(v), 1000);
    t.push(1);
    expect(said).toEqual([1]);
    t.push(2);
    t.push(3);
    vi.advanceTimersByTime(999);
    expect(said).toEqual([1]);
    vi.advanceTimersByTime(1);
    expect(said).toEqual([1, 3]);
    // Nothing waiting: the interval ends quietly, and the next value goes at once.
    vi.advanceTimersByTime(1000);
    expect(said).toEqual([1, 3]);
    t.push(4);
    expect(said).toEqual([1, 3, 4]);
  });

  it('drops a waiting value when cancelled', () => {
    const said: number[] = [];
    const t = latestThrottle((v: number) => said.push(v), 1000);
    t.push(1);
    t.push(2);
    t.cancel();
    vi.advanceTimersByTime(5000);
    expect(said).toEqual([1]);
  });
});

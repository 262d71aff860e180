/** The logarithmic mean against its definition (a − b)/(ln a − ln b) and its limits L(a, a) = a, L(0, b) = 0. */
import { describe, expect, it } from 'vitest';
import { logarithmicMean } from '../../../../src/physics/filmDynamics/logarithmicMean.ts';
import { ALGEBRAIC_TOL } from '../../../tolerances.ts';

describe('logarithmic mean', () => {
  it('is (a − b)/(ln a − ln b) for well-separated values, symmetric in a and b', () => {
    for (const [a, b] of [
      [1, 2],
      [0.3, 7],
      [1e-6, 1],
      [5, 4.9],
    ] as const) {
      const definition = (a - b) / (Math.log(a) - Math.log(b));
      expect(Math.abs(logarithmicMean(a, b) / definition - 1)).toBeLessThan(ALGEBRAIC_TOL);
      expect(logarithmicMean(b, a)).toBe(logarithmicMean(a, b));
    }
  });
  it('tends to a as b → a, without the cancellation of the definition', () => {
    // L(a, a(1 + ε)) = aε/ln(1 + ε), with log1p accurate for small ε.
    for (const eps of [1e-2, 1e-3, 1e-6, 1e-9]) {
      expect(Math.abs(logarithmicMean(2, 2 * (1 + eps)) / ((2 * eps) / Math.log1p(eps)) - 1)).toBeLessThan(ALGEBRAIC_TOL);
    }
    expect(logarithmicMean(2, 2)).toBe(2);
  });
  it('is 0 when either value is 0, and lies between the geometric and arithmetic means', () => {
    expect([logarithmicMean(0, 3), logarithmicMean(3, 0), logarithmicMean(0, 0)]).toEqual([0, 0, 0]);
    for (const [a, b] of [
      [1, 9],
      [0.01, 0.02],
    ] as const) {
      expect(logarithmicMean(a, b)).toBeGreaterThan(Math.sqrt(a * b));
      expect(logarithmicMean(a, b)).toBeLessThan((a + b) / 2);
    }
  });
});

/**
 * Chebyshev semi-iteration against linear algebra done independently: a small symmetric
 * positive-definite system solved directly (Gaussian elimination), its D⁻¹A spectrum known in closed
 * form, and the Chebyshev polynomial's bound 1/T_K((b + a)/(b − a)) = 1/cosh(K acosh(·)).
 */
import { describe, expect, it } from 'vitest';
import { chebyshevIterations, chebyshevSchedule } from '../../../../src/physics/filmDynamics/chebyshevSchedule.ts';
import { CHEBYSHEV_DIRECT_TOL } from '../../../tolerances.ts';

/**
 * A ring of n cells, (1 + 2w) x_c − w (x_{c−1} + x_{c+1}) = b_c: D⁻¹A has the eigenvalues
 * 1 − (2w/(1 + 2w)) cos(2πk/n), from 1/(1 + 2w) (k = 0) up to (1 + 4w)/(1 + 2w) (k = n/2, n even).
 */
const ring = (n: number, w: number) => ({
  n,
  w,
  d: 1 + 2 * w,
  apply: (x: Float64Array, c: number) => (1 + 2 * w) * x[c]! - w * (x[(c + n - 1) % n]! + x[(c + 1) % n]!),
  lower: 1 / (1 + 2 * w),
  upper: (1 + 4 * w) / (1 + 2 * w),
});

/** K Chebyshev steps from x0 with the schedule, as solveSurfactant runs them. */
function iterate(system: ReturnType<typeof ring>, b: Float64Array, x0: Float64Array, schedule: ReturnType<typeof chebyshevSchedule>) {
  let [previous, x] = [Float64Array.from(x0), Float64Array.from(x0)];
  for (let k = 0; k < schedule.step.length; k++) {
    const next = new Float64Array(system.n);
    for (let c = 0; c < system.n; c++) {
      const z = (b[c]! - system.apply(x, c)) / system.d;
      next[c] = x[c]! + schedule.momentum[k]! * (x[c]! - previous[c]!) + schedule.step[k]! * z;
    }
    [previous, x] = [x, next];
  }
  return x;
}

/** Gaussian elimination with partial pivoting on the dense matrix. */
function solveDirect(system: ReturnType<typeof ring>, b: Float64Array): Float64Array {
  const { n } = system;
  const m = Array.from({ length: n }, (_, r) => {
    const row = new Float64Array(n + 1);
    const unit = new Float64Array(n);
    for (let c = 0; c < n; c++) {
      unit.fill(0);
      unit[c] = 1;
      row[c] = system.apply(unit, r);
    }
    row[n] = b[r]!;
    return row;
  });
  for (let p = 0; p < n; p++) {
    let best = p;
    for (let r = p + 1; r < n; r++) if (Math.abs(m[r]![p]!) > Math.abs(m[best]![p]!)) best = r;
    [m[p], m[best]] = [m[best]!, m[p]!];
    for (let r = p + 1; r < n; r++) {
      const f = m[r]![p]! / m[p]![p]!;
      for (let c = p; c <= n; c++) m[r]![c]! -= f * m[p]![c]!;
    }
  }
  const x = new Float64Array(n);
  for (let r = n - 1; r >= 0; r--) {
    let s = m[r]![n]!;
    for (let c = r + 1; c < n; c++) s -= m[r]![c]! * x[c]!;
    x[r] = s / m[r]![r]!;
  }
  return x;
}

const norm = (a: Float64Array, b: Float64Array) => Math.sqrt(a.reduce((s, v, i) => s + (v - b[i]!) ** 2, 0));
/** A reproducible right side with every mode in it. */
const rightSide = (n: number) => Float64Array.from({ length: n }, (_, c) => Math.sin(1.7 * c) + 0.3 * Math.cos(0.2 * c * c) + 1);

describe('Chebyshev semi-iteration', () => {
  it('K is the least count whose bound 1/T_K((b + a)/(b − a)) reaches the reduction', () => {
    for (const [a, b, reduction] of [
      [0.5, 1.5, 1e-3],
      [1 / 301, 2, 1e-3],
      [1e-4, 2, 1e-6],
    ] as const) {
      const k = chebyshevIterations(a, b, reduction);
      const bound = (K: number) => 1 / Math.cosh(K * Math.acosh((b + a) / (b - a)));
      expect(bound(k)).toBeLessThanOrEqual(reduction);
      if (k > 1) expect(bound(k - 1)).toBeGreaterThan(reduction);
      expect(chebyshevSchedule(a, b, k).reduction).toBeCloseTo(bound(k), 12);
    }
  });

  it('one step with a + b = 2 is a Jacobi sweep (x₁ = x₀ + D⁻¹(b − Ax₀))', () => {
    const schedule = chebyshevSchedule(0.25, 1.75, 1);
    expect(schedule.step[0]).toBe(1);
    expect(schedule.momentum[0]).toBe(0);
  });

  it('converges to the directly solved system, and each K reaches its bound on the error', () => {
    const system = ring(40, 30);
    const b = rightSide(system.n);
    const exact = solveDirect(system, b);
    const x0 = new Float64Array(system.n);
    const many = iterate(system, b, x0, chebyshevSchedule(system.lower, system.upper, 400));
    expect(norm(many, exact) / norm(x0, exact)).toBeLessThan(CHEBYSHEV_DIRECT_TOL);
    for (const k of [5, 20, 60]) {
      const schedule = chebyshevSchedule(system.lower, system.upper, k);
      // D is a multiple of the identity here, so the D-norm bound is the Euclidean one.
      expect(norm(iterate(system, b, x0, schedule), exact) / norm(x0, exact)).toBeLessThanOrEqual(schedule.reduction * (1 + 1e-9));
    }
  });

  it('with a above the smallest eigenvalue it still converges, more slowly; with b = 2 above the largest it loses only speed', () => {
    const system = ring(40, 30);
    const b = rightSide(system.n);
    const exact = solveDirect(system, b);
    const x0 = new Float64Array(system.n);
    const start = norm(x0, exact);
    const tooHigh = iterate(system, b, x0, chebyshevSchedule(4 * system.lower, system.upper, 200));
    const safeUpper = iterate(system, b, x0, chebyshevSchedule(system.lower, 2, 200));
    expect(norm(tooHigh, exact) / start).toBeLessThan(1e-3);
    expect(norm(safeUpper, exact) / start).toBeLessThan(CHEBYSHEV_DIRECT_TOL);
  });
});

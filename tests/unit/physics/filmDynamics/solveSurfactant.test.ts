/**
 * The surfactant solve on the film's own systems at high wave Courant numbers: the eigenvalues of
 * D⁻¹A lie within the bounds its schedule assumes (measured by power iteration), and its K
 * iterations reduce the error, in the D-norm ‖e‖_D² = Σ d_c e_c², by at least the schedule's
 * guarantee, the exact solution taken from the same iteration run far past convergence.
 */
import { describe, expect, it } from 'vitest';
import { chebyshevSchedule } from '../../../../src/physics/filmDynamics/chebyshevSchedule.ts';
import { type FilmSimulation, createFilmSimulation, stepFilm } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import {
  SURFACTANT_EIGEN_UPPER,
  SURFACTANT_SOLVE_REDUCTION,
  solveSurfactant,
  surfactantStiffness,
} from '../../../../src/physics/filmDynamics/solveSurfactant.ts';
import { type TimeStepRule, timeStep } from '../../../../src/physics/filmDynamics/timeStep.ts';

/** Three times the flow's step: a wave Courant number near 30. */
const tripled: TimeStepRule = (grid, numbers) => 3 * timeStep(grid, numbers);
const CASES: [string, Record<string, number>, TimeStepRule?][] = [
  ['the defaults', {}],
  ['a thin surfactant-rich film (Γ0 1e-6, h̄ 20 nm)', { surfactantMolM2: 1e-6, thicknessNm: 20 }],
  ['a thick film (h̄ 20 µm)', { thicknessNm: 20000 }],
  ['the defaults at three times the step', {}, tripled],
];
const GRID_N = 12;
const STEPS = 5;

/** A seeded film a few steps on, its last system built again from its Γ and edge prediction. */
function filmAfterSteps(given: Record<string, number>, rule?: TimeStepRule): FilmSimulation {
  const sim = createFilmSimulation({ gridN: GRID_N, seed: 3, ...given }, rule ? { timeStep: rule } : {});
  for (let s = 0; s < STEPS; s++) stepFilm(sim);
  return sim;
}

/** y = D⁻¹A x on the system the last solve built. */
function applyPreconditioned(sim: FilmSimulation, x: Float64Array, y: Float64Array): void {
  const { cellWeight, diagonal } = sim.work.surfactant;
  const nb = sim.grid.cellNeighbor;
  for (let c = 0; c < sim.grid.cellCount; c++) {
    let off = 0;
    for (let s = 0; s < 4; s++) off += cellWeight[4 * c + s]! * x[nb[4 * c + s]!]!;
    y[c] = (diagonal[c]! * x[c]! - off) / diagonal[c]!;
  }
}

/** The largest eigenvalue of a matrix similar to a symmetric one with positive eigenvalues, by power iteration (shift s: of M − sI). */
function largestEigenvalue(sim: FilmSimulation, shift: number): number {
  const cells = sim.grid.cellCount;
  let x = Float64Array.from({ length: cells }, (_, c) => Math.sin(0.37 * c) + 1.1);
  const y = new Float64Array(cells);
  let lambda = 0;
  for (let k = 0; k < 3000; k++) {
    applyPreconditioned(sim, x, y);
    for (let c = 0; c < cells; c++) y[c] = y[c]! - shift * x[c]!;
    const size = Math.hypot(...y);
    lambda = y.reduce((s, v, c) => s + v * x[c]!, 0) / x.reduce((s, v) => s + v * v, 0);
    x = y.map((v) => v / size);
  }
  return lambda + shift;
}

describe('the surfactant solve on the film’s systems', () => {
  for (const [name, given, rule] of CASES) {
    it(`${name}: eigenvalues of D⁻¹A within [1/(1 + r), 2] and K iterations reach the guaranteed reduction`, () => {
      const sim = filmAfterSteps(given, rule);
      const { grid, dt, state, work, solveSchedule } = sim;
      const r = surfactantStiffness(grid, sim.numbers, dt);
      const waveCourant = (Math.sqrt(sim.numbers.marangoni) * dt) / grid.minSpacing;
      // The system of the film now, solved for δ = Γ' − Γ by the schedule's K iterations.
      solveSurfactant(grid, dt, state.gamma, work.prediction, work.surfactant, solveSchedule);
      const reached = Float64Array.from(work.surfactant.solution);
      // Its largest eigenvalue below the Gershgorin bound, its smallest above the schedule's lower bound.
      const largest = largestEigenvalue(sim, 0);
      const smallest = largestEigenvalue(sim, largest);
      expect(largest).toBeLessThan(SURFACTANT_EIGEN_UPPER);
      expect(smallest).toBeGreaterThanOrEqual(solveSchedule.lower);
      expect(solveSchedule.lower).toBeCloseTo(1 / (1 + r), 12);
      // The exact solution: the same iteration run 20 times as long (its own bound ~1e-60).
      const long = chebyshevSchedule(solveSchedule.lower, solveSchedule.upper, 20 * solveSchedule.step.length);
      const residual = solveSurfactant(grid, dt, state.gamma, work.prediction, work.surfactant, long);
      expect(residual).toBeLessThan(1e-10);
      const exact = work.surfactant.solution;
      const dNorm = (x: Float64Array) => Math.sqrt(x.reduce((s, v, c) => s + work.surfactant.diagonal[c]! * (v - exact[c]!) ** 2, 0));
      // The iterations start from δ = 0 (Γ' = Γ).
      const reduction = dNorm(reached) / dNorm(new Float64Array(grid.cellCount));
      console.log(
        `${name}: wave Courant ${waveCourant.toFixed(1)}, r ${r.toPrecision(3)}, λ in [${smallest.toPrecision(3)}, ${largest.toPrecision(4)}], ` +
          `K ${solveSchedule.step.length}, error reduced ×${reduction.toExponential(2)}`,
      );
      expect(reduction).toBeLessThanOrEqual(SURFACTANT_SOLVE_REDUCTION);
    });
  }
});

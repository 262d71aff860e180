/**
 * The ends of the documented domain: no NaN or Infinity anywhere and no negative thickness or
 * surfactant over 10⁴ steps, whether the film settles, is blown thin or ruptures and bursts.
 */
import { describe, expect, it } from 'vitest';
import { createFilmSimulation, stepFilm } from '../../../../src/physics/filmDynamics/filmSimulation.ts';

const STEPS = 10_000;
/** The coarsest grid (4 cells per face side) keeps 5 × 10⁴ steps to a few seconds; robustness does not need resolution. */
const GRID_N = 4;

describe('extremes', () => {
  const cases: Record<string, number>[] = [
    { radiusMm: 10 },
    { radiusMm: 100 },
    { surfactantMolM2: 1e-8 },
    { surfactantMolM2: 1e-6 },
    { windMps: 2, seed: 3 },
  ];
  for (const c of cases) {
    it(`${JSON.stringify(c)}: finite fields, η ≥ 0, Γ ≥ 0 for ${STEPS} steps`, () => {
      const sim = createFilmSimulation({ gridN: GRID_N, ...c });
      let bad = 0;
      for (let s = 0; s < STEPS; s++) {
        stepFilm(sim);
        for (const v of sim.state.eta) if (!(v >= 0 && v < Infinity)) bad++;
        for (const v of sim.state.gamma) if (!(v >= 0 && v < Infinity)) bad++;
        for (const v of sim.state.edgeVelocity) if (!Number.isFinite(v)) bad++;
      }
      expect(bad).toBe(0);
      expect(Number.isFinite(sim.state.surfactantResidual)).toBe(true);
    });
  }
});

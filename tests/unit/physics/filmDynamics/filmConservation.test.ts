/**
 * Conservation laws of eq. (17) and what the parameters promise: without evaporation or rupture
 * the film's volume ∫h dA and its surfactant ∫Γ dA are constant (both obey a continuity equation);
 * evaporation at E takes exactly E·t off the mean thickness and no surfactant; a seed fixes the
 * starting film and so the whole run.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { createFilmSimulation, filmSeconds, stepFilm } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { elasticWaveTimeStep, timeStep } from '../../../../src/physics/filmDynamics/timeStep.ts';
import { meanThicknessNm, sphereIntegral } from '../../../../src/physics/filmDynamics/filmMeasures.ts';
import { CONSERVATION_REL_TOL, EVAPORATION_REL_TOL, FLOAT_TOLERANCE } from '../../../tolerances.ts';

/** At most 10⁴ steps, and at most 40 film seconds (the light wind thins the film to rupture within minutes), on 6 cells per face side. */
const LONG_RUN_STEPS = 10_000;
const LONG_RUN_SECONDS = 40;
const SMALL_GRID_N = 6;

for (const [rule, stepRule] of [
  ["the flow's step", timeStep],
  ['the elastic-wave step', elasticWaveTimeStep],
] as const) {
  describe(`without evaporation, ${rule}`, () => {
    // A seeded film in a light wind: it flows for the whole run (drains, is blown, settles).
    const sim = createFilmSimulation({ gridN: SMALL_GRID_N, seed: 5, windMps: 0.1 }, { timeStep: stepRule });
    const steps = Math.min(LONG_RUN_STEPS, Math.ceil(LONG_RUN_SECONDS / sim.stepSeconds));
    let worstVolume = 0;
    let worstSurfactant = 0;
    let fastest = 0;
    beforeAll(() => {
      const volume0 = sphereIntegral(sim, sim.state.eta);
      const surfactant0 = sphereIntegral(sim, sim.state.gamma);
      for (let s = 0; s < steps; s++) {
        stepFilm(sim);
        worstVolume = Math.max(worstVolume, Math.abs(sphereIntegral(sim, sim.state.eta) / volume0 - 1));
        worstSurfactant = Math.max(worstSurfactant, Math.abs(sphereIntegral(sim, sim.state.gamma) / surfactant0 - 1));
        if (s < 100) for (const u of sim.state.edgeVelocity) fastest = Math.max(fastest, Math.abs(u));
      }
    });
    it('the film flowed and nothing ruptured', () => {
      expect(fastest).toBeGreaterThan(1e-3);
      expect(sim.state.holes).toHaveLength(0);
      expect(sim.state.intact.every((v) => v === 1)).toBe(true);
    });
    it(`∫h dA is conserved over the run`, () => expect(worstVolume).toBeLessThan(CONSERVATION_REL_TOL));
    it(`∫Γ dA is conserved over the run`, () => expect(worstSurfactant).toBeLessThan(CONSERVATION_REL_TOL));
  });
}

describe('evaporation at E', () => {
  const [thicknessNm, evaporationNmS, ruptureThicknessNm] = [200, 100, 10];
  it('removes E·t of the mean thickness and no surfactant until the film ruptures, no later than the mean reaches the rupture thickness', () => {
    const sim = createFilmSimulation({ gridN: SMALL_GRID_N, thicknessNm, evaporationNmS, ruptureThicknessNm });
    const surfactant0 = sphereIntegral(sim, sim.state.gamma);
    const lastChance = (thicknessNm - ruptureThicknessNm) / evaporationNmS + sim.stepSeconds;
    while (sim.state.holes.length === 0 && filmSeconds(sim) < lastChance) {
      const seconds = filmSeconds(sim);
      expect(Math.abs(meanThicknessNm(sim) / (thicknessNm - evaporationNmS * seconds) - 1)).toBeLessThan(EVAPORATION_REL_TOL);
      expect(Math.abs(sphereIntegral(sim, sim.state.gamma) / surfactant0 - 1)).toBeLessThan(EVAPORATION_REL_TOL);
      stepFilm(sim);
    }
    expect(sim.state.holes.length).toBeGreaterThan(0);
    // Checked at every step of the film's life, about 1.9 s at 62 ms a step.
    expect(sim.state.steps).toBeGreaterThan(20);
  });
});

describe('the seed', () => {
  const run = (seed: number) => {
    const sim = createFilmSimulation({ gridN: SMALL_GRID_N, seed, windMps: 0.05 });
    const start = Float64Array.from(sim.state.eta);
    for (let s = 0; s < 200; s++) stepFilm(sim);
    return { sim, start };
  };
  it('0 is the uniform film', () => expect(createFilmSimulation({ gridN: SMALL_GRID_N }).state.eta.every((v) => v === 1)).toBe(true));
  it('the same seed gives identical fields; another seed, another film', () => {
    const [a, b, c] = [run(42), run(42), run(43)];
    expect(a.sim.state.eta).toEqual(b.sim.state.eta);
    expect(a.sim.state.gamma).toEqual(b.sim.state.gamma);
    expect(a.sim.state.edgeVelocity).toEqual(b.sim.state.edgeVelocity);
    expect(a.start.some((v, i) => Math.abs(v - c.start[i]!) > 1e-3)).toBe(true);
  });
  it('a perturbed film keeps the mean thickness and Γ/η = 1', () => {
    const sim = createFilmSimulation({ gridN: SMALL_GRID_N, seed: 7, thicknessNm: 600 });
    expect(sim.state.eta.some((v) => Math.abs(v - 1) > 0.02)).toBe(true);
    expect(Math.abs(meanThicknessNm(sim) / 600 - 1)).toBeLessThan(FLOAT_TOLERANCE);
    expect(sim.state.gamma).toEqual(sim.state.eta);
  });
});

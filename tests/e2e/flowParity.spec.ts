import { BOTH_BACKENDS, expect, test } from './fixtures.ts';
import { createFilmSimulation, stepFilm } from '../../src/physics/filmDynamics/filmSimulation.ts';
import { cubeSphereGrid } from '../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { nearestCell } from '../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { FLOW_GPU_CHEBYSHEV_RESIDUAL_MAX, FLOW_GPU_FLOW_STEP_FIELD_TOL, FLOW_GPU_VELOCITY_TOL, PADDED_START_TOL } from '../tolerances.ts';

/** A small seeded film with wind and evaporation, so every pass moves something (two transport sub-steps a step). */
const STEADY = { gridN: 16, seed: 7, windMps: 0.1, evaporationNmS: 5 };
/** 4.9 film seconds of 24 ms steps: the drainage, the wind's circulation and its steady state, or with a turning wind half a turn. */
const STEPS = 200;
const CASES = [
  { name: 'a steady wind', parameters: STEADY },
  { name: 'a wind turning at 36°/s', parameters: { ...STEADY, windTurnDegS: 36 } },
];

for (const { name, parameters: PARAMETERS } of CASES)
  test(
    `the GPU film equals its float64 twin after 200 steps from the same seeded start, in ${name}`,
    { tag: BOTH_BACKENDS },
    async ({ parityPage: page }) => {
      const gpu = await page.evaluate(([p, steps]) => window.runFlow!(p, steps), [PARAMETERS, STEPS] as const);
      const twin = createFilmSimulation(PARAMETERS);
      for (let k = 0; k < STEPS; k++) stepFilm(twin);
      const worst = (a: readonly number[], b: Float64Array) => a.reduce((w, v, i) => Math.max(w, Math.abs(v - b[i]!)), 0);
      const etaError = worst(gpu.eta, twin.state.eta);
      const gammaError = worst(gpu.gamma, twin.state.gamma);
      const velocityError = worst(gpu.edgeVelocity, twin.state.edgeVelocity);
      const speed = twin.state.edgeVelocity.reduce((w, v) => Math.max(w, Math.abs(v)), 0);
      // The GPU's residual is its solve's from the film reached, the solve of the next step: the twin's of that step.
      stepFilm(twin);
      const twinResidual = twin.state.surfactantResidual;
      console.log(
        `flow GPU vs twin, ${name}, N ${PARAMETERS.gridN}, ${STEPS} steps: η ${etaError.toExponential(2)}, Γ ${gammaError.toExponential(2)}, ` +
          `u ${velocityError.toExponential(2)} of ${speed.toExponential(2)}; residual GPU ${gpu.surfactantResidual.toExponential(2)}, twin ${twinResidual.toExponential(2)}`,
      );
      expect(gpu.steps).toBe(STEPS);
      // Nothing ruptured in either (a burst is flowBurst.spec.ts's).
      expect(twin.state.holes).toEqual([]);
      expect(gpu.intact.every((v) => v === 1)).toBe(true);
      expect(gpu.holes).toEqual([]);
      expect(speed, 'the film moves').toBeGreaterThan(0.01);
      expect(etaError).toBeLessThanOrEqual(FLOW_GPU_FLOW_STEP_FIELD_TOL);
      expect(gammaError).toBeLessThanOrEqual(FLOW_GPU_FLOW_STEP_FIELD_TOL);
      expect(velocityError).toBeLessThanOrEqual(FLOW_GPU_VELOCITY_TOL);
      expect(gpu.eta.every((v) => v >= 0)).toBe(true);
      expect(gpu.surfactantResidual).toBeGreaterThan(0);
      expect(gpu.surfactantResidual).toBeLessThanOrEqual(FLOW_GPU_CHEBYSHEV_RESIDUAL_MAX);
    },
  );

test('the film’s padded start made on the CPU, drawn until the simulation’s programs are compiled, equals the GPU’s start and halo passes', async ({
  parityPage: page,
}) => {
  const { cpu, gpu } = await page.evaluate((p) => window.startPaddedFilms!(p), { gridN: 12, seed: 3 });
  expect(cpu).toHaveLength(gpu.length);
  // η and Γ near 1, intact 1: the halo's weighted sums in float32 against float64 rounded once.
  const worst = cpu.reduce((w, v, i) => Math.max(w, Math.abs(v - gpu[i]!)), 0);
  expect(worst).toBeLessThanOrEqual(PADDED_START_TOL);
  expect(
    cpu.some((v, i) => i % 4 === 0 && v !== 1),
    'a seeded start is not uniform',
  ).toBe(true);
});

test('air blown along +y at the equator moves the film there downwind: thicker ahead of the patch, thinner behind', async ({
  parityPage: page,
}) => {
  const still = { gridN: 16 };
  const steps = 20;
  const [calm, blown] = await page.evaluate(
    ([p, n]) => [window.runFlow!(p, n), window.runFlow!(p, n, { center: [1, 0, 0], velocityMps: [0, 0.5, 0] })],
    [still, steps] as const,
  );
  // 0.3 rad either side of the patch's centre, along the blow.
  const grid = cubeSphereGrid(still.gridN);
  const [ahead, behind] = [0.3, -0.3].map((a) => nearestCell(grid, Math.cos(a), Math.sin(a), 0));
  const change = (c: number) => blown.eta[c]! - calm.eta[c]!;
  console.log(`blow: η ahead ${change(ahead!).toExponential(2)}, behind ${change(behind!).toExponential(2)}`);
  expect(change(ahead!)).toBeGreaterThan(1e-3);
  expect(change(behind!)).toBeLessThan(-1e-3);
});

/**
 * `npm run bench:flow`: the speed of the float64 film-flow simulation (src/physics/filmDynamics) in Node,
 * the reference a GPU port is checked against. For 64² and 128² cells per cube face it prints
 * steps per second, film seconds per wall second, the wall and CPU time per cell-step, the step and
 * its surfactant solve's iterations, and what the run reached: the solve's residual and the drift
 * of the conserved totals. Benchmarks measure; the tests check.
 */
import { createFilmSimulation, stepFilm } from '../../src/physics/filmDynamics/filmSimulation.ts';
import { sphereIntegral } from '../../src/physics/filmDynamics/filmMeasures.ts';
import { SPEED_FILM } from './flowSpeed.ts';

/** Steps timed per grid after a few untimed ones (a seeded, gently blown film, so every pass has work). */
const RUNS = [
  { gridN: 64, warmUp: 5, steps: 60 },
  { gridN: 128, warmUp: 3, steps: 20 },
];

console.log(
  '| cells per face | cells | step (ms) | solve iterations | steps/s | film s per wall s | wall ns per cell-step | CPU ns per cell-step | worst solve residual | volume drift |',
);
console.log('|---|---|---|---|---|---|---|---|---|---|');
for (const { gridN, warmUp, steps } of RUNS) {
  const sim = createFilmSimulation({ gridN, ...SPEED_FILM });
  const volume0 = sphereIntegral(sim, sim.state.eta);
  for (let s = 0; s < warmUp; s++) stepFilm(sim);
  let worstResidual = 0;
  const cpu0 = process.cpuUsage();
  const wall0 = performance.now();
  for (let s = 0; s < steps; s++) {
    stepFilm(sim);
    worstResidual = Math.max(worstResidual, sim.state.surfactantResidual);
  }
  const wallS = (performance.now() - wall0) / 1000;
  const cpu = process.cpuUsage(cpu0);
  const cpuS = (cpu.user + cpu.system) / 1e6;
  const cellSteps = steps * sim.grid.cellCount;
  const drift = sphereIntegral(sim, sim.state.eta) / volume0 - 1;
  console.log(
    `| ${gridN}² | ${sim.grid.cellCount} | ${(sim.stepSeconds * 1e3).toPrecision(3)} | ${sim.solveSchedule.step.length} | ${(steps / wallS).toFixed(2)} | ${((steps * sim.stepSeconds) / wallS).toFixed(3)} | ${((wallS / cellSteps) * 1e9).toFixed(0)} | ${((cpuS / cellSteps) * 1e9).toFixed(0)} | ${worstResidual.toExponential(1)} | ${drift.toExponential(1)} |`,
  );
}

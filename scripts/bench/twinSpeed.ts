/** The float64 twin's speed in Node (src/physics/filmDynamics): steps per wall second at each grid of the plan. */
import { createFilmSimulation, stepFilm } from '../../src/physics/filmDynamics/filmSimulation.ts';
import { type FlowSpeedPlan, SPEED_FILM, type SimulationSpeed, simulationSpeed, timedStepsPerSecond } from './flowSpeed.ts';

export function twinSpeed(plan: FlowSpeedPlan): SimulationSpeed[] {
  return plan.grids.map((gridN) => {
    const sim = createFilmSimulation({ gridN, ...SPEED_FILM });
    const rate = timedStepsPerSecond(
      plan,
      (count) => {
        for (let k = 0; k < count; k++) stepFilm(sim);
      },
      () => {},
    );
    return simulationSpeed(gridN, sim.stepSeconds, rate);
  });
}

/**
 * The GPU port's speed on the benchmark page's renderer: a GpuFilmSimulation per grid of the plan,
 * its batches synced by a 1-pixel read-back of the film target, and the draws of one step as the
 * renderer counts them (renderer.info.render.calls, its reset per render held off around the step).
 */
import type { WebGLRenderer } from 'three';
import { GpuFilmSimulation } from '../../../src/gpuFilmDynamics/gpuFilmSimulation.ts';
import { type FlowSpeedPlan, type GpuSimulationSpeed, SPEED_FILM, simulationSpeed, timedStepsPerSecond } from '../flowSpeed.ts';

/** The draws `work` makes on `renderer`, as its info counts them. */
function drawsOf(renderer: WebGLRenderer, work: () => void): number {
  const info = renderer.info;
  const autoReset = info.autoReset;
  info.autoReset = false;
  info.reset();
  try {
    work();
    return info.render.calls;
  } finally {
    info.autoReset = autoReset;
    info.reset();
  }
}

export function gpuFlowSpeed(renderer: WebGLRenderer, plan: FlowSpeedPlan): GpuSimulationSpeed[] {
  const texel = new Float32Array(4);
  return plan.grids.map((gridN) => {
    const sim = new GpuFilmSimulation(renderer, { gridN, ...SPEED_FILM });
    try {
      const sync = () => renderer.readRenderTargetPixels(sim.stateTargets.film, 0, 0, 1, 1, texel);
      const rate = timedStepsPerSecond(plan, (count) => sim.step(count), sync);
      const drawsPerStep = drawsOf(renderer, () => sim.step(1));
      sync();
      if (!texel.every(Number.isFinite)) throw new Error(`the film at grid ${gridN} holds ${texel.join(', ')} after ${sim.steps} steps`);
      return { ...simulationSpeed(gridN, sim.stepSeconds, rate), drawsPerStep };
    } finally {
      sim.dispose();
    }
  });
}

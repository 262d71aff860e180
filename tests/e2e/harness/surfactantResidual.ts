/**
 * The residual the GPU's surfactant solve reaches, measured by the test harness itself: from a
 * GpuFilmSimulation's public state (its film and edge velocities, its parameters, grid, Δt and
 * schedule) it draws the step's first passes, the prediction and the solve, with the simulation's
 * own programs (drawPredictionAndSolve) into targets of its own, reads back the system's right side
 * b − AΓ and diagonal, the weights and the solved increment δ, and sums ‖b − Aδ‖ over the cells on
 * the CPU (float64): relative to ‖b‖, the residual of δ = 0, it is the twin's surfactantResidual,
 * ‖b − AΓ'‖/‖b − AΓ‖, for the step the simulation takes next (in its wind; a blow is not drawn).
 */
import type { WebGLRenderer } from 'three';
import { cubeSphereHalo } from '../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { surfaceWind, windAngleRad } from '../../../src/physics/filmDynamics/windDirection.ts';
import { FullscreenPass } from '../../../src/gpu/fullscreenPass.ts';
import { cellTexelIndex } from '../../../src/gpuFilmDynamics/flowAtlas.ts';
import { flowGridTextures } from '../../../src/gpuFilmDynamics/flowGridTextures.ts';
import { passMaterials } from '../../../src/gpuFilmDynamics/flowPasses.ts';
import { allTargets, flowTargets } from '../../../src/gpuFilmDynamics/flowTargets.ts';
import { SURFACTANT_SWEEP, SURFACTANT_SYSTEM, SURFACTANT_WEIGHTS } from '../../../src/gpuFilmDynamics/flowTexels.ts';
import { type FlowUniformName, allFlowUniforms, flowUniformSets } from '../../../src/gpuFilmDynamics/flowUniforms.ts';
import type { GpuFilmSimulation } from '../../../src/gpuFilmDynamics/gpuFilmSimulation.ts';
import { type DrawPass, drawPredictionAndSolve } from '../../../src/gpuFilmDynamics/solvePasses.ts';
import { readTexels, texelFloat, texelVector } from './filmReadback.ts';

/** The GPU solve's texels for the simulation's next step: its system, weights and solved increment, per texel of the cell atlas. */
function solveTexels(renderer: WebGLRenderer, sim: GpuFilmSimulation) {
  const textures = flowGridTextures(sim.grid, cubeSphereHalo(sim.grid));
  const { parameters, numbers, grid, dt, transportSubsteps } = sim;
  const sets = flowUniformSets({ parameters, numbers, grid, dt, transportSubsteps, renewSteps: 0, textures });
  const uniforms = allFlowUniforms(sets);
  uniforms.uSurfaceWind.value = surfaceWind(numbers, windAngleRad(parameters, sim.steps * sim.stepSeconds));
  const materials = passMaterials(sets);
  const targets = flowTargets(grid.n);
  const fullscreen = new FullscreenPass();
  const draw: DrawPass = (pass, target, inputs) => {
    for (const [name, value] of Object.entries(inputs)) uniforms[name as FlowUniformName].value = value;
    renderer.setRenderTarget(target);
    fullscreen.render(renderer, materials[pass]);
  };
  const { film, edgeVelocity } = sim.stateTargets;
  const previous = renderer.getRenderTarget();
  const solved = drawPredictionAndSolve(draw, targets, { film: film.texture, edgeVelocity: edgeVelocity.texture }, sim.solveSchedule);
  renderer.setRenderTarget(previous);
  const texels = {
    system: readTexels(renderer, targets.system),
    weights: readTexels(renderer, targets.weights),
    solved: readTexels(renderer, solved),
  };
  for (const target of allTargets(targets)) target.dispose();
  for (const material of Object.values(materials)) material.dispose();
  for (const texture of Object.values(textures)) texture.dispose();
  fullscreen.dispose();
  return texels;
}

/** ‖b − Aδ‖/‖b‖ of the GPU's solve for the simulation's next step (0 when b = 0: Γ solves it already). */
export function surfactantResidual(renderer: WebGLRenderer, sim: GpuFilmSimulation): number {
  const { system, weights, solved } = solveTexels(renderer, sim);
  const { n, cellCount, cellNeighbor } = sim.grid;
  const increment = (c: number) => texelFloat(SURFACTANT_SWEEP, solved, cellTexelIndex(n, c), 'X');
  let [initial, reached] = [0, 0];
  for (let c = 0; c < cellCount; c++) {
    const t = cellTexelIndex(n, c);
    const rhs = texelFloat(SURFACTANT_SYSTEM, system, t, 'RHS');
    const sides = texelVector(SURFACTANT_WEIGHTS, weights, t, 'SIDES');
    // Row c of A: the diagonal at c, −w_e at the neighbour across side e.
    let residual = rhs - texelFloat(SURFACTANT_SYSTEM, system, t, 'DIAGONAL') * increment(c);
    sides.forEach((w, s) => (residual += w * increment(cellNeighbor[4 * c + s]!)));
    initial += rhs * rhs;
    reached += residual * residual;
  }
  return initial > 0 ? Math.sqrt(reached / initial) : 0;
}

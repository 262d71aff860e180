import { rejectValue } from '../../input/validate.ts';
import { type CubeSphereGrid, cubeSphereGrid } from './cubeSphereGrid.ts';
import { type CubeSphereHalo, cubeSphereHalo, padField, paddedSampler } from './cubeSphereSampler.ts';
import type { FilmHole } from './filmHoles.ts';
import { type FlowNumbers, flowNumbers } from './flowNumbers.ts';
import { type FlowParameters, validateFlowParameters } from './flowParameters.ts';
import { initialFilm } from './initialFilm.ts';
import { type EdgePrediction, predictEdgeVelocity } from './predictEdgeVelocity.ts';
import { reconstructCellVelocity } from './reconstructCellVelocity.ts';
import { openHole, ruptureFilm } from './ruptureFilm.ts';
import type { ChebyshevSchedule } from './chebyshevSchedule.ts';
import { type SurfactantWork, correctEdgeVelocity, solveSurfactant, surfactantSolveSchedule, surfactantWork } from './solveSurfactant.ts';
import { type TimeStepRule, WIND_SURFACE_FACTOR, timeStep, transportSubsteps } from './timeStep.ts';
import { type TransportWork, transportFilm, transportWork } from './transportFilm.ts';
import { windAngleRad } from './windDirection.ts';

/** The evolving fields, in the units of eq. (17) (docs/flow.md#the-model). */
export interface FilmState {
  /** η/η0 per cell. */
  readonly eta: Float64Array;
  /** Γ/Γ0 per cell. */
  readonly gamma: Float64Array;
  /** u·n_e per edge (n_e from the edge's cell A to B), in U. */
  readonly edgeVelocity: Float64Array;
  /** 1 where the film is whole, 0 where a hole has opened. */
  readonly intact: Uint8Array;
  readonly holes: FilmHole[];
  /** Steps taken. */
  steps: number;
  /** Simulated seconds still to run (less than one step) after the last advance. */
  pendingSeconds: number;
  /** The relative residual the last surfactant solve reached. */
  surfactantResidual: number;
}

export interface FilmSimulation {
  readonly parameters: FlowParameters;
  readonly numbers: FlowNumbers;
  readonly grid: CubeSphereGrid;
  readonly halo: CubeSphereHalo;
  /** The fixed step in R/U, and in seconds. */
  readonly dt: number;
  readonly stepSeconds: number;
  /** The surfactant solve's Chebyshev iterations, fixed by the parameters and Δt (surfactantSolveSchedule). */
  readonly solveSchedule: ChebyshevSchedule;
  /** The transport's sub-steps of Δt/S each (transportSubsteps). */
  readonly transportSubsteps: number;
  readonly state: FilmState;
  readonly work: StepWork;
}

interface StepWork {
  readonly cellVelocity: Float64Array;
  readonly paddedCellVelocity: Float64Array;
  /** The air at the surface along each edge's normal for the wind along +x and along +y (φ = 0 and 90°). */
  readonly windAlongX: Float64Array;
  readonly windAlongY: Float64Array;
  /** The air at the surface along each edge's normal at the step's wind direction (windDirection.ts). */
  readonly windAlongNormal: Float64Array;
  readonly prediction: EdgePrediction;
  readonly surfactant: SurfactantWork;
  readonly transport: TransportWork;
  readonly sampleVector: ReturnType<typeof paddedSampler>;
}

export interface FilmSimulationOptions {
  /** The rule that sizes Δt: the flow's (timeStep, the default) or, for comparison runs, elasticWaveTimeStep. */
  readonly timeStep?: TimeStepRule;
}

/** A film at rest on a bubble, every parameter checked first (validateFlowParameters). */
export function createFilmSimulation(given: Partial<Record<string, unknown>> = {}, options: FilmSimulationOptions = {}): FilmSimulation {
  const parameters = validateFlowParameters(given);
  const numbers = flowNumbers(parameters);
  const grid = cubeSphereGrid(parameters.gridN);
  const halo = cubeSphereHalo(grid);
  const dt = (options.timeStep ?? timeStep)(grid, numbers);
  const { eta, gamma } = initialFilm(grid, parameters.seed);
  // The air at the surface: WIND_SURFACE_FACTOR × the wind projected onto the tangent plane, for
  // the wind along +x and along +y; the wind at angle φ is cos φ × the first + sin φ × the second.
  const windAlongX = new Float64Array(grid.edgeCount);
  const windAlongY = new Float64Array(grid.edgeCount);
  for (let e = 0; e < grid.edgeCount; e++) {
    windAlongX[e] = WIND_SURFACE_FACTOR * numbers.wind * grid.edgeNormal[3 * e]!;
    windAlongY[e] = WIND_SURFACE_FACTOR * numbers.wind * grid.edgeNormal[3 * e + 1]!;
  }
  return {
    parameters,
    numbers,
    grid,
    halo,
    dt,
    stepSeconds: dt * numbers.timeScaleS,
    solveSchedule: surfactantSolveSchedule(grid, numbers, dt),
    transportSubsteps: transportSubsteps(grid, numbers, dt),
    state: {
      eta,
      gamma,
      edgeVelocity: new Float64Array(grid.edgeCount),
      intact: new Uint8Array(grid.cellCount).fill(1),
      holes: [],
      steps: 0,
      pendingSeconds: 0,
      surfactantResidual: 0,
    },
    work: {
      cellVelocity: new Float64Array(3 * grid.cellCount),
      paddedCellVelocity: new Float64Array(3 * halo.paddedCell.length),
      windAlongX,
      windAlongY,
      windAlongNormal: new Float64Array(grid.edgeCount),
      prediction: { predicted: new Float64Array(grid.edgeCount), marangoniCoefficient: new Float64Array(grid.edgeCount) },
      surfactant: surfactantWork(grid),
      transport: transportWork(grid),
      sampleVector: paddedSampler(halo, 3),
    },
  };
}

/**
 * The air at the surface along each edge's normal for the step from the film time of `sim`: the
 * wind along +x when it does not turn, else turned to the angle φ at the step's start
 * (windDirection.ts), u_air,e = cos φ u_air,e(+x) + sin φ u_air,e(+y).
 */
function windAlongNormal(sim: FilmSimulation): Float64Array {
  const { work } = sim;
  if (sim.parameters.windTurnDegS === 0) return work.windAlongX;
  const angle = windAngleRad(sim.parameters, filmSeconds(sim));
  const [c, s] = [Math.cos(angle), Math.sin(angle)];
  for (let e = 0; e < work.windAlongNormal.length; e++) work.windAlongNormal[e] = c * work.windAlongX[e]! + s * work.windAlongY[e]!;
  return work.windAlongNormal;
}

/**
 * One fixed step Δt of eq. (17), as the passes a GPU mirrors (docs/flow.md#the-step): the wind's
 * direction at the step's start, reconstruct cell velocities, halo, advect + force at edges,
 * surfactant solve, edge correction, conservative transport of η and Γ (in sub-steps),
 * evaporation, rupture and rims.
 */
export function stepFilm(sim: FilmSimulation): void {
  const { grid, halo, numbers, dt, state, work } = sim;
  const air = windAlongNormal(sim);
  reconstructCellVelocity(grid, state.edgeVelocity, work.cellVelocity);
  padField(halo, work.cellVelocity, 3, work.paddedCellVelocity);
  predictEdgeVelocity(
    grid,
    numbers,
    dt,
    {
      cellVelocity: work.cellVelocity,
      paddedCellVelocity: work.paddedCellVelocity,
      sample: work.sampleVector,
      eta: state.eta,
      intact: state.intact,
      windAlongNormal: air,
    },
    work.prediction,
  );
  state.surfactantResidual = solveSurfactant(grid, dt, state.gamma, work.prediction, work.surfactant, sim.solveSchedule);
  correctEdgeVelocity(grid, work.prediction, state.gamma, work.surfactant.solution, state.edgeVelocity);
  const substeps = sim.transportSubsteps;
  for (let k = 0; k < substeps; k++) transportFilm(grid, dt / substeps, state.edgeVelocity, state.eta, state.gamma, work.transport);
  evaporate(state, numbers.evaporation * dt);
  ruptureFilm(
    { halo, parameters: sim.parameters, numbers, eta: state.eta, gamma: state.gamma, intact: state.intact, holes: state.holes },
    dt,
  );
  state.steps++;
}

/** Dη/Dt = … − e of eq. (17): every intact cell loses e·Δt of η, never going below 0 (GPU pass 7). */
function evaporate(state: FilmState, loss: number): void {
  if (loss === 0) return;
  for (let c = 0; c < state.eta.length; c++) if (state.intact[c] === 1) state.eta[c] = Math.max(0, state.eta[c]! - loss);
}

/**
 * Runs as many whole steps as `seconds` (plus what was left over last time) holds, `onStep` called
 * after each (a long run's progress); returns how many.
 */
export function advanceFilm(sim: FilmSimulation, seconds: number, onStep?: () => void): number {
  const { state, stepSeconds } = sim;
  state.pendingSeconds += seconds;
  let taken = 0;
  // A relative slack of 1e-9 so that k·Δt seconds take k steps despite rounding.
  while (state.pendingSeconds >= stepSeconds * (1 - 1e-9)) {
    stepFilm(sim);
    state.pendingSeconds -= stepSeconds;
    taken++;
    onStep?.();
  }
  state.pendingSeconds = Math.max(0, state.pendingSeconds);
  return taken;
}

/**
 * A puncture's direction from the bubble's centre (the simulation's frame, any length): three
 * finite numbers, not all 0, whose length √(x² + y² + z²) is finite too; otherwise a
 * ParameterError naming `puncture`.
 */
export function checkPunctureDirection(x: number, y: number, z: number): void {
  const length = Math.hypot(x, y, z);
  if (![x, y, z].every(Number.isFinite) || !(length > 0 && length < Infinity))
    rejectValue('puncture', [x, y, z], 'a direction from the centre [x, y, z]: three finite numbers, not all 0, of a finite length');
}

/** Pricks the film at a direction (checkPunctureDirection): a hole opens there and bursts outward. */
export function punctureFilm(sim: FilmSimulation, x: number, y: number, z: number): void {
  checkPunctureDirection(x, y, z);
  openHole(sim.state.holes, x, y, z);
}

/** Simulated seconds so far. */
export const filmSeconds = (sim: FilmSimulation): number => sim.state.steps * sim.stepSeconds;

/** The padded η, for samplers (kept here so the sampler module needs no state). */
export const paddedEta = (sim: FilmSimulation): Float64Array => padField(sim.halo, sim.state.eta, 1);

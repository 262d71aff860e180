import type { CubeSphereGrid } from './cubeSphereGrid.ts';
import type { FlowNumbers } from './flowNumbers.ts';

/** The Courant number of the step at the reference flow speed, on the mean centre spacing (1.31 × the closest). */
export const COURANT_NUMBER = 1;
/**
 * The largest Marangoni-elastic wave Courant number √M·Δt over the closest centre spacing: the
 * surfactant solve converges at any, in a number of iterations that grows with it
 * (surfactantSolveSchedule); this caps that number and the slowing of the elastic waves by the
 * implicit step (docs/flow.md#stability-and-the-time-step).
 */
export const WAVE_COURANT_MAX = 10;
/**
 * The Courant number of each transport sub-step at the reference flow speed, on the closest centre
 * spacing: the explicit upwind transport is accurate (its limiter idle) while a cell's outflow per
 * sub-step stays below its content, and a thin film carried through a cell by the air empties it
 * at Courant numbers near 1 (docs/flow.md#stability-and-the-time-step).
 */
export const TRANSPORT_COURANT_NUMBER = 0.7;
/** Air outside a sphere slides past its surface at up to 3/2 of the wind speed (potential flow). */
export const WIND_SURFACE_FACTOR = 1.5;

/**
 * The reference flow speed (in U): the fastest of the film's free drainage speed g·η/Cr at the
 * mean thickness (η = 1: gravity against air friction, eq. (17) without Marangoni stress, the
 * terminal speed of a film falling freely) and the air at the surface, WIND_SURFACE_FACTOR × wind.
 */
export const referenceFlowSpeed = (numbers: FlowNumbers): number =>
  Math.max(numbers.gravity / numbers.airFriction, WIND_SURFACE_FACTOR * numbers.wind);

/**
 * The fixed time step Δt (in R/U), sized by the flow (docs/flow.md#stability-and-the-time-step):
 * COURANT_NUMBER × the mean centre spacing over the reference flow speed, and at most
 * WAVE_COURANT_MAX × the closest spacing over the elastic wave speed √M. Domain: any valid
 * parameters (every number positive and finite).
 */
export function timeStep(grid: CubeSphereGrid, numbers: FlowNumbers): number {
  const advection = (COURANT_NUMBER * grid.meanSpacing) / referenceFlowSpeed(numbers);
  const waves = (WAVE_COURANT_MAX * grid.minSpacing) / Math.sqrt(numbers.marangoni);
  return Math.min(advection, waves);
}

/**
 * The transport's sub-steps per step: the least count S for which Δt/S carries the reference flow
 * speed at most TRANSPORT_COURANT_NUMBER × the closest centre spacing (S ≥ 1).
 */
export const transportSubsteps = (grid: CubeSphereGrid, numbers: FlowNumbers, dt: number): number =>
  Math.max(1, Math.ceil((dt * referenceFlowSpeed(numbers)) / (TRANSPORT_COURANT_NUMBER * grid.minSpacing)));

/**
 * A step resolving the Marangoni-elastic waves, for comparison runs against the flow's step:
 * 0.5 × the closest centre spacing over max(1 m/s, WIND_SURFACE_FACTOR × wind, √M·U), a wave
 * Courant number of at most 0.5.
 */
export function elasticWaveTimeStep(grid: CubeSphereGrid, numbers: FlowNumbers): number {
  const speed = Math.max(1, WIND_SURFACE_FACTOR * numbers.wind, Math.sqrt(numbers.marangoni));
  return (0.5 * grid.minSpacing) / speed;
}

/** A rule that sizes the fixed step for a grid and a parameter set. */
export type TimeStepRule = (grid: CubeSphereGrid, numbers: FlowNumbers) => number;

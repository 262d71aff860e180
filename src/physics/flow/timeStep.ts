import type { CubeSphereGrid } from './cubeSphereGrid.ts';
import type { FlowNumbers } from './flowNumbers.ts';

/** The Courant number the step is sized for: a film at the reference speed crosses half the closest cell spacing per step. */
export const COURANT_NUMBER = 0.5;
/** Air outside a sphere slides past its surface at up to 3/2 of the wind speed (potential flow). */
export const WIND_SURFACE_FACTOR = 1.5;

/**
 * The fixed time step Δt (in R/U): COURANT_NUMBER × the closest centre spacing over the fastest
 * speed the film is expected to carry or signal: 1 m/s (drainage stays well below it), the air at
 * the surface (WIND_SURFACE_FACTOR × wind), and the Marangoni-elastic wave speed √M (the solve is
 * implicit in it, but a Courant number near 1 keeps the fixed Jacobi count converged).
 * docs/flow.md#stability-and-the-time-step.
 */
export function timeStep(grid: CubeSphereGrid, numbers: FlowNumbers): number {
  const speed = Math.max(1, WIND_SURFACE_FACTOR * numbers.wind, Math.sqrt(numbers.marangoni));
  return (COURANT_NUMBER * grid.minSpacing) / speed;
}

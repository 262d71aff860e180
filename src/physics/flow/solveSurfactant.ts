import type { CubeSphereGrid } from './cubeSphereGrid.ts';
import type { EdgePrediction } from './predictEdgeVelocity.ts';

/** Jacobi sweeps per step: a fixed count, so a GPU runs the same passes (docs/flow.md#the-surfactant-solve). */
export const SURFACTANT_JACOBI_SWEEPS = 12;

export interface SurfactantWork {
  /** w_e = Δt L_e Γ̄_e c_e/d_e, the edge weight of the 5-point operator. */
  readonly weight: Float64Array;
  /** The same weights per cell and side (4 per cell), so a sweep reads them in order. */
  readonly cellWeight: Float64Array;
  readonly rhs: Float64Array;
  readonly diagonal: Float64Array;
  /** Ping-pong buffers; the solution ends in `solution`. */
  readonly solution: Float64Array;
  readonly scratch: Float64Array;
}

export const surfactantWork = (grid: CubeSphereGrid): SurfactantWork => ({
  weight: new Float64Array(grid.edgeCount),
  cellWeight: new Float64Array(4 * grid.cellCount),
  rhs: new Float64Array(grid.cellCount),
  diagonal: new Float64Array(grid.cellCount),
  solution: new Float64Array(grid.cellCount),
  scratch: new Float64Array(grid.cellCount),
});

/**
 * The surfactant at the end of the step, implicit in the Marangoni term (GPU pass 4: one draw for the system, one per sweep):
 * DΓ/Dt = −Γ∇·u of eq. (17) in flux form, A_c Γ'_c = A_c Γ_c − Δt Σ_e L_e Γ_e u_e, with the edge
 * velocity u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e and the edge mean Γ̄_e of the old Γ as the flux's Γ,
 * which makes the system symmetric positive definite:
 *   (A_c + Σ_e w_e) Γ'_c − Σ_e w_e Γ'_nb = A_c Γ_c − Δt Σ_e L_e (u*·n_out)_e Γ̄_e.
 * (With Γ̄_e in both parts, a film whose u* the old Γ's gradient balances returns Γ' = Γ and u = 0.)
 * Solved by SURFACTANT_JACOBI_SWEEPS Jacobi sweeps from Γ; returns the residual reached relative to
 * that of the starting guess, ‖b − AΓ'‖/‖b − AΓ‖ (0 when Γ already solves it). The Γ' found sets the velocity only: the step then moves η and Γ with
 * conservative fluxes, so an unconverged solve costs accuracy, never mass.
 */
export function solveSurfactant(
  grid: CubeSphereGrid,
  dt: number,
  gamma: Float64Array,
  prediction: EdgePrediction,
  work: SurfactantWork,
  sweeps = SURFACTANT_JACOBI_SWEEPS,
): number {
  const { area, cellEdge, cellEdgeSign, cellNeighbor, edgeA, edgeB, edgeLength, edgeDistance } = grid;
  const { predicted, marangoniCoefficient } = prediction;
  const { weight, cellWeight, rhs, diagonal } = work;
  for (let e = 0; e < grid.edgeCount; e++) {
    const meanGamma = 0.5 * (gamma[edgeA[e]!]! + gamma[edgeB[e]!]!);
    weight[e] = (dt * edgeLength[e]! * meanGamma * marangoniCoefficient[e]!) / edgeDistance[e]!;
  }
  for (let c = 0; c < grid.cellCount; c++) {
    let b = area[c]! * gamma[c]!;
    let d = area[c]!;
    for (let s = 0; s < 4; s++) {
      const e = cellEdge[4 * c + s]!;
      const meanGamma = 0.5 * (gamma[c]! + gamma[cellNeighbor[4 * c + s]!]!);
      b -= dt * edgeLength[e]! * cellEdgeSign[4 * c + s]! * predicted[e]! * meanGamma;
      d += weight[e]!;
      cellWeight[4 * c + s] = weight[e]!;
    }
    rhs[c] = b;
    diagonal[c] = d;
  }
  let x = work.solution;
  let next = work.scratch;
  x.set(gamma);
  const initial = jacobiSweep(grid.cellCount, cellNeighbor, work, x, next);
  for (let k = 1; k < sweeps; k++) {
    const swap = x;
    x = next;
    next = swap;
    jacobiSweep(grid.cellCount, cellNeighbor, work, x, next);
  }
  if (next !== work.solution) work.solution.set(next);
  // One more sweep into the scratch buffer measures the residual of the solution.
  const reached = jacobiSweep(grid.cellCount, cellNeighbor, work, work.solution, work.scratch);
  return initial > 0 ? reached / initial : 0;
}

/** One Jacobi sweep x → next; returns ‖b − Ax‖₂ of the x it started from. */
function jacobiSweep(cells: number, neighbor: Int32Array, work: SurfactantWork, x: Float64Array, next: Float64Array): number {
  const { cellWeight, rhs, diagonal } = work;
  let residual2 = 0;
  for (let c = 0; c < cells; c++) {
    const k = 4 * c;
    const sum =
      rhs[c]! +
      cellWeight[k]! * x[neighbor[k]!]! +
      cellWeight[k + 1]! * x[neighbor[k + 1]!]! +
      cellWeight[k + 2]! * x[neighbor[k + 2]!]! +
      cellWeight[k + 3]! * x[neighbor[k + 3]!]!;
    residual2 += (sum - diagonal[c]! * x[c]!) ** 2;
    next[c] = sum / diagonal[c]!;
  }
  return Math.sqrt(residual2);
}

/** u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e: the end-of-step edge velocity (GPU pass 5). */
export function correctEdgeVelocity(grid: CubeSphereGrid, prediction: EdgePrediction, solvedGamma: Float64Array, out: Float64Array): void {
  const { edgeA, edgeB, edgeDistance } = grid;
  for (let e = 0; e < grid.edgeCount; e++) {
    const slope = (solvedGamma[edgeB[e]!]! - solvedGamma[edgeA[e]!]!) / edgeDistance[e]!;
    out[e] = prediction.predicted[e]! - prediction.marangoniCoefficient[e]! * slope;
  }
}

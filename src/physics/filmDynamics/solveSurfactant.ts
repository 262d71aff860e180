import { type ChebyshevSchedule, chebyshevIterations, chebyshevSchedule } from './chebyshevSchedule.ts';
import type { CubeSphereGrid } from './cubeSphereGrid.ts';
import type { FlowNumbers } from './flowNumbers.ts';
import type { EdgePrediction } from './predictEdgeVelocity.ts';

/** The error reduction each step's solve is sized for, 1/T_K(θ/δ) over the bounded spectrum (docs/flow.md#the-surfactant-solve). */
export const SURFACTANT_SOLVE_REDUCTION = 1e-3;
/**
 * The upper bound b on the eigenvalues of D⁻¹A: D⁻¹A = I − D⁻¹W with W ≥ 0 the off-diagonal weights
 * and Σ_e w_e < d_c in every row, so by Gershgorin every eigenvalue is below 1 + max_c Σ_e w_e/d_c < 2.
 */
export const SURFACTANT_EIGEN_UPPER = 2;

/** max_c Σ_e (L_e/d_e)/A_c over the cells: the grid's part of the bound on Σ_e w_e/A_c (in 1/R²). */
export function couplingDensity(grid: CubeSphereGrid): number {
  const { area, cellEdge, edgeLength, edgeDistance } = grid;
  let densest = 0;
  for (let c = 0; c < grid.cellCount; c++) {
    let sum = 0;
    for (let s = 0; s < 4; s++) sum += edgeLength[cellEdge[4 * c + s]!]! / edgeDistance[cellEdge[4 * c + s]!]!;
    densest = Math.max(densest, sum / area[c]!);
  }
  return densest;
}

/**
 * The bound r on Σ_e w_e/A_c that the parameters give without the film: w_e = Δt L_e Γ̄_e c_e/d_e
 * with c_e = M/(η_e/Δt + Cr) ≤ MΔt/η_e, so w_e ≤ MΔt² (L_e/d_e)(Γ̄_e/η_e), and Γ/η stays 1 along the
 * flow of a film that starts with it (it grows only by evaporation): r = MΔt² max_c Σ_e (L_e/d_e)/A_c.
 * It is the square of the wave Courant number √MΔt/Δx times about 4.
 */
export const surfactantStiffness = (grid: CubeSphereGrid, numbers: FlowNumbers, dt: number): number =>
  numbers.marangoni * dt * dt * couplingDensity(grid);

/**
 * The Chebyshev schedule of a simulation's surfactant solve, fixed by its parameters so a GPU runs
 * the same passes: the eigenvalues of D⁻¹A lie in [1/(1 + r), SURFACTANT_EIGEN_UPPER] (the lower
 * bound: xᵀAx ≥ Σ A_c x_c² and xᵀDx = Σ (A_c + Σ_e w_e) x_c²), r from surfactantStiffness, and K the
 * least count reaching SURFACTANT_SOLVE_REDUCTION there. Where r underestimates the film's (Γ/η
 * above 1 after evaporation, or the edge means Γ̄_e above the logarithmic η_e), the lowest modes
 * converge more slowly, never unstably.
 */
export function surfactantSolveSchedule(grid: CubeSphereGrid, numbers: FlowNumbers, dt: number): ChebyshevSchedule {
  const lower = 1 / (1 + surfactantStiffness(grid, numbers, dt));
  return chebyshevSchedule(lower, SURFACTANT_EIGEN_UPPER, chebyshevIterations(lower, SURFACTANT_EIGEN_UPPER, SURFACTANT_SOLVE_REDUCTION));
}

export interface SurfactantWork {
  /** w_e = Δt L_e Γ̄_e c_e/d_e, the edge weight of the 5-point operator. */
  readonly weight: Float64Array;
  /** The same weights per cell and side (4 per cell), so a sweep reads them in order. */
  readonly cellWeight: Float64Array;
  readonly rhs: Float64Array;
  readonly diagonal: Float64Array;
  /** The iterates δ_k (ending as the solution δ = Γ' − Γ), δ_{k−1} and δ_{k+1}, taking turns. */
  readonly solution: Float64Array;
  readonly previous: Float64Array;
  readonly scratch: Float64Array;
}

export const surfactantWork = (grid: CubeSphereGrid): SurfactantWork => ({
  weight: new Float64Array(grid.edgeCount),
  cellWeight: new Float64Array(4 * grid.cellCount),
  rhs: new Float64Array(grid.cellCount),
  diagonal: new Float64Array(grid.cellCount),
  solution: new Float64Array(grid.cellCount),
  previous: new Float64Array(grid.cellCount),
  scratch: new Float64Array(grid.cellCount),
});

/**
 * The surfactant at the end of the step, implicit in the Marangoni term (GPU pass 4: one draw for
 * the weights, one for the system, one per iteration): DΓ/Dt = −Γ∇·u of eq. (17) in flux form,
 * A_c Γ'_c = A_c Γ_c − Δt Σ_e L_e Γ_e u_e, with the edge velocity u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e
 * and the edge mean Γ̄_e of the old Γ as the flux's Γ, which makes the system symmetric positive
 * definite:
 *   (A_c + Σ_e w_e) Γ'_c − Σ_e w_e Γ'_nb = A_c Γ_c − Δt Σ_e L_e (u*·n_out)_e Γ̄_e.
 * (With Γ̄_e in both parts, a film whose u* the old Γ's gradient balances returns Γ' = Γ and u = 0.)
 * Solved for the increment, Aδ = b − AΓ with δ = Γ' − Γ, its right side assembled from the fluxes
 * and the differences Γ_c − Γ_nb (so float32 rounds the step's change, not Γ), by the schedule's
 * Chebyshev-accelerated Jacobi iterations from δ = 0 (chebyshevSchedule.ts); leaves δ in
 * `work.solution` and returns the residual reached relative to that of Γ, ‖b − AΓ'‖/‖b − AΓ‖ (0
 * when Γ already solves it). The Γ' found sets the velocity only: the step then moves η and Γ with
 * conservative fluxes, so an unconverged solve costs accuracy, never mass.
 */
export function solveSurfactant(
  grid: CubeSphereGrid,
  dt: number,
  gamma: Float64Array,
  prediction: EdgePrediction,
  work: SurfactantWork,
  schedule: Pick<ChebyshevSchedule, 'momentum' | 'step'>,
): number {
  const { area, cellEdge, cellEdgeSign, cellNeighbor, edgeA, edgeB, edgeLength, edgeDistance } = grid;
  const { predicted, marangoniCoefficient } = prediction;
  const { weight, cellWeight, rhs, diagonal } = work;
  for (let e = 0; e < grid.edgeCount; e++) {
    const meanGamma = 0.5 * (gamma[edgeA[e]!]! + gamma[edgeB[e]!]!);
    weight[e] = (dt * edgeLength[e]! * meanGamma * marangoniCoefficient[e]!) / edgeDistance[e]!;
  }
  for (let c = 0; c < grid.cellCount; c++) {
    // b − AΓ, from the fluxes and the differences of Γ, never as the difference of A_cΓ_c-sized terms.
    let b = 0;
    let d = area[c]!;
    for (let s = 0; s < 4; s++) {
      const e = cellEdge[4 * c + s]!;
      const neighbor = gamma[cellNeighbor[4 * c + s]!]!;
      b -=
        dt * edgeLength[e]! * cellEdgeSign[4 * c + s]! * predicted[e]! * 0.5 * (gamma[c]! + neighbor) + weight[e]! * (gamma[c]! - neighbor);
      d += weight[e]!;
      cellWeight[4 * c + s] = weight[e]!;
    }
    rhs[c] = b;
    diagonal[c] = d;
  }
  // δ_0 = 0, and δ_{−1} = 0 too (the first iteration's momentum is 0).
  let [previous, x, next] = [work.previous, work.solution, work.scratch];
  x.fill(0);
  previous.fill(0);
  let initial = 0;
  for (let k = 0; k < schedule.step.length; k++) {
    const residual = chebyshevSweep(grid.cellCount, cellNeighbor, work, x, previous, next, schedule.momentum[k]!, schedule.step[k]!);
    if (k === 0) initial = residual;
    [previous, x, next] = [x, next, previous];
  }
  if (x !== work.solution) work.solution.set(x);
  // One more sweep into the scratch buffer measures the residual of the solution.
  const reached = chebyshevSweep(grid.cellCount, cellNeighbor, work, work.solution, work.solution, work.scratch, 0, 1);
  return initial > 0 ? reached / initial : 0;
}

/**
 * One Chebyshev-accelerated Jacobi iteration x → next = x + momentum (x − previous) + step z,
 * z = D⁻¹(b − Ax) (next may not be x or previous); returns ‖b − Ax‖₂ of the x it started from.
 */
function chebyshevSweep(
  cells: number,
  neighbor: Int32Array,
  work: SurfactantWork,
  x: Float64Array,
  previous: Float64Array,
  next: Float64Array,
  momentum: number,
  step: number,
): number {
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
    const residual = sum - diagonal[c]! * x[c]!;
    residual2 += residual * residual;
    next[c] = x[c]! + momentum * (x[c]! - previous[c]!) + (step * residual) / diagonal[c]!;
  }
  return Math.sqrt(residual2);
}

/** u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e with Γ' = Γ + δ: the end-of-step edge velocity (GPU pass 5). */
export function correctEdgeVelocity(
  grid: CubeSphereGrid,
  prediction: EdgePrediction,
  gamma: Float64Array,
  increment: Float64Array,
  out: Float64Array,
): void {
  const { edgeA, edgeB, edgeDistance } = grid;
  for (let e = 0; e < grid.edgeCount; e++) {
    const a = edgeA[e]!;
    const b = edgeB[e]!;
    const slope = (gamma[b]! - gamma[a]! + (increment[b]! - increment[a]!)) / edgeDistance[e]!;
    out[e] = prediction.predicted[e]! - prediction.marangoniCoefficient[e]! * slope;
  }
}

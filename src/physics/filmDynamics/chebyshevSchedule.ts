/**
 * Chebyshev semi-iteration on a Jacobi-preconditioned symmetric positive-definite system
 * (Golub and Varga, Numer. Math. 3, 1961; the three-term form of Saad, "Iterative Methods for
 * Sparse Linear Systems", 2nd ed., Algorithm 12.1): with z_k = D⁻¹(b − A x_k),
 *
 *   x_1 = x_0 + z_0/θ,
 *   x_{k+1} = x_k + ρ_k ρ_{k−1} (x_k − x_{k−1}) + (2ρ_k/δ) z_k,
 *
 * θ = (b + a)/2, δ = (b − a)/2, ρ_0 = δ/θ, ρ_k = 1/(2θ/δ − ρ_{k−1}), where the eigenvalues of D⁻¹A
 * lie in [a, b]. The error after K steps is p_K(D⁻¹A) e_0 with max_[a, b] |p_K| = 1/T_K(θ/δ)
 * (T_K the Chebyshev polynomial); eigenvalues in (0, a) are damped too, more slowly
 * (|p_K| < 1 on (0, b]), so an a above the smallest eigenvalue costs convergence, never stability;
 * a b below the largest would not be safe. No inner products: each step is one pass over the cells
 * with two per-step coefficients, which a GPU takes as uniforms (docs/flow.md#the-surfactant-solve).
 */

/** The coefficients of each step: x_{k+1} = x_k + momentum[k] (x_k − x_{k−1}) + step[k] z_k. */
export interface ChebyshevSchedule {
  /** The bounds [a, b] on the eigenvalues of D⁻¹A the schedule was made for. */
  readonly lower: number;
  readonly upper: number;
  readonly momentum: Float64Array;
  readonly step: Float64Array;
  /** 1/T_K(θ/δ): the error reduction the K steps guarantee for eigenvalues in [a, b]. */
  readonly reduction: number;
}

/**
 * The least K with 1/T_K(θ/δ) ≤ reduction, T_K(x) = cosh(K acosh x) for x ≥ 1.
 * Domain: 0 < lower < upper, 0 < reduction < 1.
 */
export const chebyshevIterations = (lower: number, upper: number, reduction: number): number =>
  Math.max(1, Math.ceil(Math.acosh(1 / reduction) / Math.acosh((upper + lower) / (upper - lower))));

/** The schedule of `iterations` steps for eigenvalues in [lower, upper]; domain 0 < lower < upper, iterations ≥ 1. */
export function chebyshevSchedule(lower: number, upper: number, iterations: number): ChebyshevSchedule {
  const theta = (upper + lower) / 2;
  const delta = (upper - lower) / 2;
  const momentum = new Float64Array(iterations);
  const step = new Float64Array(iterations);
  step[0] = 1 / theta;
  let rho = delta / theta;
  for (let k = 1; k < iterations; k++) {
    const next = 1 / ((2 * theta) / delta - rho);
    momentum[k] = next * rho;
    step[k] = (2 * next) / delta;
    rho = next;
  }
  const reduction = 1 / Math.cosh(iterations * Math.acosh(theta / delta));
  return { lower, upper, momentum, step, reduction };
}

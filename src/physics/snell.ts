import { type Complex } from './complex.ts';

/**
 * Snell's law, eqs (1) and (2): n_a sin θ_i = n_b sin θ_r = n_c sin θ_t.
 *
 * Returns cos θ_j in a medium of index `n` for light arriving from the outside medium (index
 * `nOutside`, angle θ_i with cosine `cosIncidence`), as a complex number: real in [0, 1] while
 * the wave propagates, purely imaginary (Im ≥ 0, the branch on which the evanescent wave decays)
 * past the critical angle. Computed as n cos θ_j = √((n − n_a)(n + n_a) + (n_a cos θ_i)²), which
 * keeps its digits near grazing incidence and gives cos θ_i back when n = n_a.
 * Domain: n, nOutside in [1, 4], cosIncidence in [0, 1].
 */
export function refractedCos(n: number, nOutside: number, cosIncidence: number): Complex {
  const nCosIncidence = nOutside * cosIncidence;
  const nCos2 = (n - nOutside) * (n + nOutside) + nCosIncidence * nCosIncidence;
  return nCos2 >= 0 ? { re: Math.sqrt(nCos2) / n, im: 0 } : { re: 0, im: Math.sqrt(-nCos2) / n };
}

/** cos θ of an angle in degrees, exactly 0 at 90° (not 6e-17), so grazing is really grazing. Domain 0–90°. */
export const cosDeg = (angleDeg: number): number => Math.sin(((90 - angleDeg) * Math.PI) / 180);

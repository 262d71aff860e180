import { type Complex } from './complex.ts';

/**
 * Snell's law, eqs (1) and (2): n_a sin θ_i = n_b sin θ_r = n_c sin θ_t.
 *
 * Returns cos θ_j in a medium of index `n` for the invariant `nSinTheta` = n_a sin θ_i, as a
 * complex number: real in [0, 1] while the wave propagates, purely imaginary (Im ≥ 0, the
 * branch on which the evanescent wave decays) past the critical angle.
 * Written as √((n − n_a sin θ_i)(n + n_a sin θ_i)) / n, which keeps its digits near the
 * critical angle. Domain: n ≥ 1, 0 ≤ nSinTheta ≤ 4.
 */
export function refractedCos(nSinTheta: number, n: number): Complex {
  const nCos2 = (n - nSinTheta) * (n + nSinTheta);
  return nCos2 >= 0 ? { re: Math.sqrt(nCos2) / n, im: 0 } : { re: 0, im: Math.sqrt(-nCos2) / n };
}

/**
 * sin θ and cos θ of an angle in degrees, exact at 0° and 90° (cos 90° is 0, not 6e-17), so
 * grazing incidence is really grazing. Domain: 0 ≤ angleDeg ≤ 90.
 */
export function sinCosDeg(angleDeg: number): { sin: number; cos: number } {
  return { sin: Math.sin((angleDeg * Math.PI) / 180), cos: Math.sin(((90 - angleDeg) * Math.PI) / 180) };
}

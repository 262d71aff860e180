import { type Complex, type RefractiveIndex, cAdd, cDiv, cMul, cSqrt, realIndex } from './complex.ts';

/**
 * Snell's law, eqs (1) and (2): n_a sin θ_i = n_b sin θ_r = n_c sin θ_t.
 *
 * Returns cos θ_j in a medium of index `n` for light arriving from the outside medium (index
 * `nOutside`, angle θ_i with cosine `cosIncidence`), as a complex number: real in [0, 1] while
 * the wave propagates, purely imaginary (Im ≥ 0, the branch on which the evanescent wave decays)
 * past the critical angle. Computed as n cos θ_j = √((n − n_a)(n + n_a) + (n_a cos θ_i)²), which
 * keeps its digits near grazing incidence and gives cos θ_i back when n = n_a.
 * An absorbing medium ñ = n + ik (k > 0) takes the same root in complex arithmetic, on the branch
 * Im(ñ cos θ_j) ≥ 0 where the wave decays into the medium (docs/physics.md#absorbing-media); k = 0
 * is the real path exactly.
 * Domain: real n, nOutside in [1, 4], or ñ within COMPLEX_INDEX_DOMAIN; cosIncidence in [0, 1].
 */
export function refractedCos(n: RefractiveIndex, nOutside: number, cosIncidence: number): Complex {
  const nCosIncidence = nOutside * cosIncidence;
  const real = realIndex(n);
  if (real === null) return absorbingCos(n as Complex, nOutside, nCosIncidence);
  const nCos2 = (real - nOutside) * (real + nOutside) + nCosIncidence * nCosIncidence;
  return nCos2 >= 0 ? { re: Math.sqrt(nCos2) / real, im: 0 } : { re: 0, im: Math.sqrt(-nCos2) / real };
}

/** cos θ in an absorbing medium: (ñ cos θ) / ñ with ñ cos θ = √((ñ − n_a)(ñ + n_a) + (n_a cos θ_i)²), Im ≥ 0. */
function absorbingCos(n: Complex, nOutside: number, nCosIncidence: number): Complex {
  const square = cAdd(cMul({ re: n.re - nOutside, im: n.im }, { re: n.re + nOutside, im: n.im }), {
    re: nCosIncidence * nCosIncidence,
    im: 0,
  });
  // With k > 0, Im(ñ²) = 2nk > 0, so the principal root already has Im ≥ 0 (and Re ≥ 0).
  const root = cSqrt(square);
  const nCos = root.im < 0 ? { re: -root.re, im: -root.im } : root;
  return cDiv(nCos, n);
}

/** cos θ of an angle in degrees, exactly 0 at 90° (not 6e-17), so grazing is really grazing. Domain 0–90°. */
export const cosDeg = (angleDeg: number): number => Math.sin(((90 - angleDeg) * Math.PI) / 180);

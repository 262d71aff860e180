import { type Complex, type RefractiveIndex, cAdd, cDiv, cScale, cSub, cTimesIndex, realIndex, sameIndex } from './complex.ts';

/** Amplitude coefficients of one interface, medium 1 → medium 2. */
export interface InterfaceCoefficients {
  readonly rs: Complex;
  readonly rp: Complex;
  readonly ts: Complex;
  readonly tp: Complex;
}

const NO_INTERFACE: InterfaceCoefficients = {
  rs: { re: 0, im: 0 },
  rp: { re: 0, im: 0 },
  ts: { re: 1, im: 0 },
  tp: { re: 1, im: 0 },
};

/**
 * Fresnel amplitude coefficients from medium 1 (index n1, cos θ1) into medium 2 (n2, cos θ2),
 * in the paper's sign convention:
 *   r^s = (n1 cos θ1 − n2 cos θ2) / (n1 cos θ1 + n2 cos θ2)      eq (5)
 *   r^p = (n2 cos θ1 − n1 cos θ2) / (n2 cos θ1 + n1 cos θ2)      eq (6)
 *   t^s = 2 n1 cos θ1 / (n1 cos θ1 + n2 cos θ2)                  eq (9)
 *   t^p = 2 n1 cos θ1 / (n1 cos θ2 + n2 cos θ1)                  eq (10)
 * The reverse interface (2 → 1) is the same call with the media swapped.
 * Cosines are complex (see snell.ts), so total internal reflection gives |r| = 1; the indices may
 * be complex too, ñ = n + ik (docs/physics.md#absorbing-media), and the formulas hold unchanged.
 * Equal indices are no interface at all (r = 0, t = 1), also at grazing incidence where the
 * formulas would read 0/0; for unequal indices the denominators never vanish.
 * Domain: the indices and cosines of `refractedCos`.
 */
export function fresnelCoefficients(n1: RefractiveIndex, cos1: Complex, n2: RefractiveIndex, cos2: Complex): InterfaceCoefficients {
  if (sameIndex(n1, n2)) return NO_INTERFACE;
  const n1c1 = cTimesIndex(cos1, n1);
  const n2c2 = cTimesIndex(cos2, n2);
  const n2c1 = cTimesIndex(cos1, n2);
  const n1c2 = cTimesIndex(cos2, n1);
  const sDen = cAdd(n1c1, n2c2);
  const pDen = cAdd(n2c1, n1c2);
  return {
    rs: cDiv(cSub(n1c1, n2c2), sDen),
    rp: cDiv(cSub(n2c1, n1c2), pDen),
    ts: cDiv(cScale(n1c1, 2), sDen),
    tp: cDiv(cScale(n1c1, 2), pDen),
  };
}

/**
 * Re(ñ_c cos θ_t) / (n_a cos θ_i), the ratio of normal energy fluxes that turns |t|² into T, for
 * light from a transparent n_a into the far side ñ_c: 0 where ñ_c absorbs (it is opaque, T = 0);
 * at exact grazing incidence (cos θ_i = 0) its limit, 1 where the light meets no interface at all
 * (`noInterface`) and 0 otherwise, since no energy crosses a real interface there.
 */
export function transmittedFluxRatio(na: number, cosI: Complex, nc: RefractiveIndex, cosT: Complex, noInterface: boolean): number {
  const ncReal = realIndex(nc);
  if (ncReal === null) return 0;
  return cosI.re > 0 ? (ncReal * cosT.re) / (na * cosI.re) : noInterface ? 1 : 0;
}

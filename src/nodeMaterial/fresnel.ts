/**
 * Fresnel amplitude coefficients in TSL, medium 1 → medium 2, the paper's sign convention: r^s
 * eq (5), r^p eq (6), t^s eq (9), t^p eq (10); complex indices vec2(n, k) unchanged. Equal indices
 * are no interface. The node twin of shaders/physics/fresnel.glsl (src/physics/fresnel.ts).
 */
import { select, vec2 } from 'three/tsl';
import { type ComplexNode, cDiv, cEqual, cMul } from './complex.ts';

export interface InterfaceCoefficients {
  readonly rs: ComplexNode;
  readonly rp: ComplexNode;
  readonly ts: ComplexNode;
  readonly tp: ComplexNode;
}

/**
 * The coefficients of the interface 1 → 2, and its reverse's t on request (over the same sums, from
 * the far side's n cos θ): a coefficient made a variable is emitted whether it is read or not.
 */
function forwardWay(n1: ComplexNode, cos1: ComplexNode, n2: ComplexNode, cos2: ComplexNode) {
  const same = cEqual(n1, n2);
  const n1c1 = cMul(n1, cos1);
  const n2c2 = cMul(n2, cos2);
  const n2c1 = cMul(n2, cos1);
  const n1c2 = cMul(n1, cos2);
  const sInverse = cDiv(vec2(1, 0), n1c1.add(n2c2));
  const pInverse = cDiv(vec2(1, 0), n2c1.add(n1c2));
  const zero = vec2(0, 0);
  const one = vec2(1, 0);
  const t = (nc: ComplexNode, inverse: ComplexNode) => select(same, one, cMul(nc.mul(2), inverse)).toVar();
  const forward: InterfaceCoefficients = {
    rs: select(same, zero, cMul(n1c1.sub(n2c2), sInverse)).toVar(),
    rp: select(same, zero, cMul(n2c1.sub(n1c2), pInverse)).toVar(),
    ts: t(n1c1, sInverse),
    tp: t(n1c1, pInverse),
  };
  return { forward, reverseT: () => ({ ts: t(n2c2, sInverse), tp: t(n2c2, pInverse) }) };
}

/** Both ways of the interface 1|2: the reverse's r is the forward's negated, its t the far side's 2 n cos θ over the same sums. */
export function interfaceBothWays(
  n1: ComplexNode,
  cos1: ComplexNode,
  n2: ComplexNode,
  cos2: ComplexNode,
): { readonly forward: InterfaceCoefficients; readonly backward: InterfaceCoefficients } {
  const { forward, reverseT } = forwardWay(n1, cos1, n2, cos2);
  return { forward, backward: { rs: forward.rs.negate(), rp: forward.rp.negate(), ...reverseT() } };
}

/** The coefficients of the interface 1 → 2 (without the reverse's t, which three would emit unused). */
export const fresnelCoefficients = (n1: ComplexNode, cos1: ComplexNode, n2: ComplexNode, cos2: ComplexNode): InterfaceCoefficients =>
  forwardWay(n1, cos1, n2, cos2).forward;

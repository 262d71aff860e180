/**
 * Fresnel amplitude coefficients in TSL, medium 1 → medium 2, the paper's sign convention: r^s
 * eq (5), r^p eq (6), t^s eq (9), t^p eq (10); complex indices vec2(n, k) unchanged. Equal indices
 * are no interface. The node twin of shaders/physics/fresnel.glsl (src/physics/fresnel.ts).
 */
import { select, vec2, vec4 } from 'three/tsl';
import { type Node } from 'three/webgpu';
import { type ComplexNode, cDiv, cEqual, cMul } from './complex.ts';
import { shaderFunction } from './shaderFunction.ts';

export interface InterfaceCoefficients {
  readonly rs: ComplexNode;
  readonly rp: ComplexNode;
  readonly ts: ComplexNode;
  readonly tp: ComplexNode;
}

const INTERFACE = [
  ['n1', 'vec2'],
  ['cos1', 'vec2'],
  ['n2', 'vec2'],
  ['cos2', 'vec2'],
] as const;

/** Equal indices (no interface), and the sums eqs (5), (6), (9), (10) divide by, inverted. */
function interfaceSums(n1: ComplexNode, cos1: ComplexNode, n2: ComplexNode, cos2: ComplexNode) {
  const n1c1 = cMul(n1, cos1).toVar();
  const n2c2 = cMul(n2, cos2).toVar();
  const n2c1 = cMul(n2, cos1).toVar();
  const n1c2 = cMul(n1, cos2).toVar();
  return {
    same: cEqual(n1, n2),
    n1c1,
    n2c2,
    n2c1,
    n1c2,
    sInverse: cDiv(vec2(1, 0), n1c1.add(n2c2)),
    pInverse: cDiv(vec2(1, 0), n2c1.add(n1c2)),
  };
}

/** (r^s, r^p) of the interface 1 → 2, eqs (5), (6). */
const reflection = shaderFunction('tfcFresnelR', 'vec4', INTERFACE, (n1, cos1, n2, cos2) => {
  const { same, n1c1, n2c2, n2c1, n1c2, sInverse, pInverse } = interfaceSums(n1, cos1, n2, cos2);
  return select(same, vec4(0, 0, 0, 0), vec4(cMul(n1c1.sub(n2c2), sInverse), cMul(n2c1.sub(n1c2), pInverse)));
});

/** (t^s, t^p) of the interface 1 → 2, eqs (9), (10). */
const transmission = shaderFunction('tfcFresnelT', 'vec4', INTERFACE, (n1, cos1, n2, cos2) => {
  const { same, n1c1, sInverse, pInverse } = interfaceSums(n1, cos1, n2, cos2);
  const twice = n1c1.mul(2);
  return select(same, vec4(1, 0, 1, 0), vec4(cMul(twice, sInverse), cMul(twice, pInverse)));
});

/** The coefficients of one way, from its (r^s, r^p) and (t^s, t^p). */
const coefficients = (r: Node<'vec4'>, t: Node<'vec4'>): InterfaceCoefficients => ({ rs: r.xy, rp: r.zw, ts: t.xy, tp: t.zw });

/**
 * Both ways of the interface 1|2: the reverse's r is the forward's negated, its t the forward's
 * with the media swapped (2 n₂ cos θ₂ over the same sums).
 */
export function interfaceBothWays(
  n1: ComplexNode,
  cos1: ComplexNode,
  n2: ComplexNode,
  cos2: ComplexNode,
): { readonly forward: InterfaceCoefficients; readonly backward: InterfaceCoefficients } {
  const r = reflection(n1, cos1, n2, cos2).toVar();
  return {
    forward: coefficients(r, transmission(n1, cos1, n2, cos2).toVar()),
    backward: coefficients(r.negate(), transmission(n2, cos2, n1, cos1).toVar()),
  };
}

/** The coefficients of the interface 1 → 2. */
export const fresnelCoefficients = (n1: ComplexNode, cos1: ComplexNode, n2: ComplexNode, cos2: ComplexNode): InterfaceCoefficients =>
  coefficients(reflection(n1, cos1, n2, cos2).toVar(), transmission(n1, cos1, n2, cos2).toVar());

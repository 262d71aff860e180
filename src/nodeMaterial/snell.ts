/**
 * Snell's law in TSL, eqs (1), (2): cos θ_j in a medium of index ñ = vec2(n, k), complex past the
 * critical angle or in an absorbing medium, on the branch Im(ñ cos θ_j) ≥ 0 where the wave decays:
 * ñ cos θ_j = sqrt((ñ − n_a)(ñ + n_a) + (n_a cos θ_i)²). The node twin of shaders/physics/snell.glsl
 * (src/physics/snell.ts).
 */
import { select, sqrt, vec2 } from 'three/tsl';
import { type ComplexNode, type FloatNode, cDiv, cMul, cSqrt } from './complex.ts';
import { shaderFunction } from './shaderFunction.ts';

/** cos θ in a transparent medium of real index n. */
function realRefractedCos(n: FloatNode, nOutside: FloatNode, cosIncidence: FloatNode): ComplexNode {
  const nCosIncidence = nOutside.mul(cosIncidence);
  const nCos2 = n.sub(nOutside).mul(n.add(nOutside)).add(nCosIncidence.mul(nCosIncidence));
  return select(nCos2.greaterThanEqual(0), vec2(sqrt(nCos2).div(n), 0), vec2(0, sqrt(nCos2.negate()).div(n)));
}

/** cos θ in a medium of index ñ = vec2(n, k) for light from a transparent n_a at cos θ_i. */
export const refractedCos = shaderFunction(
  'tfcRefractedCos',
  'vec2',
  [
    ['n', 'vec2'],
    ['nOutside', 'float'],
    ['cosIncidence', 'float'],
  ],
  (n, nOutside, cosIncidence) => {
    const nCosIncidence = nOutside.mul(cosIncidence);
    const square = cMul(n.sub(vec2(nOutside, 0)), n.add(vec2(nOutside, 0))).add(vec2(nCosIncidence.mul(nCosIncidence), 0));
    const root = cSqrt(square);
    const absorbing = cDiv(select(root.y.lessThan(0), root.negate(), root), n);
    return select(n.y.equal(0), realRefractedCos(n.x, nOutside, cosIncidence), absorbing);
  },
);

/**
 * Complex arithmetic in TSL, complex numbers as vec2(re, im); sums, differences and real scaling
 * are plain vec2 operations, the rest functions of the program (shaderFunction.ts). The node twin
 * of shaders/physics/complex.glsl (src/physics/complex.ts).
 */
import { abs, cos, exp, length, select, sin, sqrt, vec2 } from 'three/tsl';
import { type Node } from 'three/webgpu';
import { shaderFunction } from './shaderFunction.ts';

export type ComplexNode = Node<'vec2'>;
export type FloatNode = Node<'float'>;

const COMPLEX_PAIR = [
  ['a', 'vec2'],
  ['b', 'vec2'],
] as const;

export const cMul = shaderFunction('tfcComplexMul', 'vec2', COMPLEX_PAIR, (a, b) =>
  vec2(a.x.mul(b.x).sub(a.y.mul(b.y)), a.x.mul(b.y).add(a.y.mul(b.x))),
);

/** a / b by Smith's algorithm (no overflow in |b|²); b ≠ 0. */
export const cDiv = shaderFunction('tfcComplexDiv', 'vec2', COMPLEX_PAIR, (a, b) => {
  const tx = b.y.div(b.x);
  const dx = b.x.add(b.y.mul(tx));
  const byX = vec2(a.x.add(a.y.mul(tx)), a.y.sub(a.x.mul(tx))).div(dx);
  const ty = b.x.div(b.y);
  const dy = b.x.mul(ty).add(b.y);
  const byY = vec2(a.x.mul(ty).add(a.y), a.y.mul(ty).sub(a.x)).div(dy);
  return select(abs(b.x).greaterThanEqual(abs(b.y)), byX, byY);
});

/** Whether a = b, both parts exactly (GLSL's `==` on vectors; TSL's `equal` is per component). */
export const cEqual = (a: ComplexNode, b: ComplexNode): Node<'bool'> => a.x.equal(b.x).and(a.y.equal(b.y));

/** Whether z is exactly 0. */
export const cIsZero = (z: ComplexNode): Node<'bool'> => z.x.equal(0).and(z.y.equal(0));

export const cAbs2 = (a: ComplexNode): FloatNode => a.dot(a);

/** e^{i z} = e^{−Im z} (cos Re z + i sin Re z) */
export const cExpI = shaderFunction('tfcComplexExpI', 'vec2', [['z', 'vec2']], (z) => vec2(cos(z.x), sin(z.x)).mul(exp(z.y.negate())));

/** The principal square root (Re ≥ 0), formed without cancellation; 0 at 0. */
export const cSqrt = shaderFunction('tfcComplexSqrt', 'vec2', [['z', 'vec2']], (z) => {
  const m = sqrt(abs(z.x).add(length(z)).mul(0.5));
  const root = select(
    z.x.greaterThanEqual(0),
    vec2(m, z.y.div(m.mul(2))),
    vec2(abs(z.y).div(m.mul(2)), select(z.y.greaterThanEqual(0), m, m.negate())),
  );
  return select(cIsZero(z), vec2(0, 0), root);
});

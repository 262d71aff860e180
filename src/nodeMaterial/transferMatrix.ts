/**
 * The reflectance of a stack of films in TSL (src/physics/transferMatrix.ts): media 0 (the light's
 * side, the outside), 1..N the films, N+1 the inside. The Airy (Rouard) recursion from the inside
 * out (Born & Wolf §1.6; Byrnes 2016, arXiv:1603.02720):
 *   Γ_N = r_{N,N+1},
 *   Γ_j = r_{j,j+1} + t_{j,j+1} t_{j+1,j} Γ_{j+1} e^{iφ_{j+1}} / (1 − r_{j+1,j} Γ_{j+1} e^{iφ_{j+1}}),
 *   φ_j = 4π ñ_j d_j cos θ_j / λ,   R = |Γ_0|² per channel, averaged over the channels.
 * The stack is src/film/filmStack.ts's texture: a row per film from the outside in, then the
 * inside, a column per spectral bin, each texel a FILM_LAYER record. The node twin of
 * shaders/physics/transferMatrix.glsl, for light from outside.
 */
import { Loop, float, int, ivec2, min, select, textureLoad, vec2 } from 'three/tsl';
import { type Node, type TextureNode } from 'three/webgpu';
import { FILM_LAYER } from '../film/filmStack.ts';
import { type ComplexNode, type FloatNode, cAbs2, cDiv, cExpI, cIsZero, cMul } from './complex.ts';
import { type Channels, channelOf, weightedSum } from './filmReflectance.ts';
import { fresnelCoefficients, interfaceBothWays } from './fresnel.ts';
import { shaderFunction } from './shaderFunction.ts';
import { refractedCos } from './snell.ts';
import { texelFloat, texelVec2 } from './texelRecords.ts';

/** The stack as the program reads it: its texture and its film count. */
export interface StackNodes {
  readonly layers: TextureNode;
  readonly count: Node<'int'>;
}

/** Row `row` of the stack at bin `bin`: its ñ and its thickness (a FOLLOWS_FIELD film takes the field's). */
function stackRow(stack: StackNodes, row: Node<'int'>, bin: Node<'int'>, fieldThicknessNm: FloatNode) {
  const t = textureLoad(stack.layers, ivec2(bin.mul(FILM_LAYER.texels), row)).toVar();
  const follows = texelFloat(t, FILM_LAYER.offsets.FOLLOWS_FIELD).equal(1);
  return {
    n: texelVec2(t, FILM_LAYER.offsets.N),
    thicknessNm: select(follows, fieldThicknessNm, texelFloat(t, FILM_LAYER.offsets.THICKNESS_NM)),
  };
}

/** One step of the recursion for one channel: Γ_j from Γ_{j+1}; r_{j,j+1} where no light crosses (the numerator exactly 0). */
const rouardStepFn = shaderFunction(
  'tfcRouardStep',
  'vec2',
  [
    ['rForward', 'vec2'],
    ['tForward', 'vec2'],
    ['rBackward', 'vec2'],
    ['tBackward', 'vec2'],
    ['gammaInner', 'vec2'],
    ['z', 'vec2'],
  ],
  (rForward, tForward, rBackward, tBackward, gammaInner, z) => {
    const echo = cMul(gammaInner, z).toVar();
    const multiple = cMul(cMul(tForward, tBackward), echo).toVar();
    const step = rForward.add(cDiv(multiple, vec2(1, 0).sub(cMul(rBackward, echo))));
    return select(cIsZero(multiple), rForward, step);
  },
);

const rouardStep = (
  forward: { r: ComplexNode; t: ComplexNode },
  backward: { r: ComplexNode; t: ComplexNode },
  gammaInner: ComplexNode,
  z: ComplexNode,
): ComplexNode => rouardStepFn(forward.r, forward.t, backward.r, backward.t, gammaInner, z);

/** R of the stack at bin `bin` (centre λ), light from the outside n_a, the channels' weighted sum. */
export function layersReflectance(
  stack: StackNodes,
  { kinds, weights }: Channels,
  bin: Node<'int'>,
  lambdaNm: FloatNode,
  nOutside: FloatNode,
  fieldThicknessNm: FloatNode,
  cosIncidence: FloatNode,
): FloatNode {
  const count = stack.count;
  const inside = stackRow(stack, count, bin, fieldThicknessNm);
  const last = stackRow(stack, count.sub(1), bin, fieldThicknessNm);
  const nOut = last.n.toVar();
  const dOut = last.thicknessNm.toVar();
  const cosOut = refractedCos(nOut, nOutside, cosIncidence).toVar();
  const c = fresnelCoefficients(nOut, cosOut, inside.n, refractedCos(inside.n, nOutside, cosIncidence));
  const gamma = kinds.map((kind) => channelOf(c, kind).r.toVar());
  Loop({ start: int(1), end: count, type: 'int', condition: '<=' }, ({ i }: { i: Node<'int'> }) => {
    const j = count.sub(i);
    const nIn = nOut.toVar();
    const cosIn = cosOut.toVar();
    const dIn = dOut.toVar();
    // Medium j: the outside at j = 0, else film row j − 1.
    const row = stackRow(stack, select(j.greaterThan(0), j.sub(1), int(0)), bin, fieldThicknessNm);
    const isOutside = j.equal(0);
    nOut.assign(select(isOutside, vec2(nOutside, 0), row.n));
    dOut.assign(select(isOutside, float(0), row.thicknessNm));
    cosOut.assign(refractedCos(nOut, nOutside, cosIncidence));
    const z = cExpI(cMul(nIn, cosIn).mul(dIn.mul(4 * Math.PI).div(lambdaNm))).toVar();
    const { forward, backward } = interfaceBothWays(nOut, cosOut, nIn, cosIn);
    kinds.forEach((kind, k) => gamma[k]!.assign(rouardStep(channelOf(forward, kind), channelOf(backward, kind), gamma[k]!, z)));
  });
  return min(
    1,
    weightedSum(
      weights,
      gamma.map((g) => cAbs2(g)),
    ),
  );
}

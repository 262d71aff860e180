/**
 * XYZ of the reflected light in TSL, eqs (15)–(18), by equal wavelength bins over
 * LAMBDA_MIN_NM–LAMBDA_MAX_NM: X = Σ over bins of W_bin × mean R over the bin's phase window. The
 * node twin of shaders/physics/binnedIntegration.glsl (src/physics/binnedIntegration.ts); the bin
 * weights (∫_bin I_in x̄, ȳ, z̄ / k) are src/film/spectralBinsTexture.ts's texture.
 */
import { If, Loop, clamp, float, int, ivec2, length, select, textureLoad, vec2, vec3 } from 'three/tsl';
import { type Node, type TextureNode, type UniformArrayNode, type UniformNode } from 'three/webgpu';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM, type PlaneCount } from '../physics/spectralWeights.ts';
import { MAX_LIGHT_LINES } from '../physics/lightLines.ts';
import { weightsRow } from '../film/spectralBinsTexture.ts';
import { type FloatNode } from './complex.ts';
import {
  type AiryTerms,
  type FilmOptics,
  meanChannelReflectance,
  reflectanceAt,
  roundTripAttenuation,
  channelSum,
} from './filmReflectance.ts';

/**
 * The bins as the program holds them (spectralBinDefines): their count, the ones visited (first ≤
 * b < end), their weights; `plane`: the colour plane a sum in one plane takes its weights and lines
 * from (a table's texel's, whose texture holds the planes one above the other), else the first.
 */
export interface SpectralBinNodes {
  readonly count: number;
  readonly first: number;
  readonly end: number;
  readonly weights: TextureNode;
  readonly plane?: Node<'int'>;
}

/**
 * A line source's lines (src/physics/lightLines.ts): `count` of them (0: the light has a spectrum
 * and the bins integrate it), each (p x̄, ȳ, z̄(λ)/k, λ in nm), a set per colour plane (plane p's
 * line i at p · MAX_LIGHT_LINES + i); spectralBinsTexture.ts sets both.
 */
export interface LightLineNodes {
  readonly values: UniformArrayNode<'vec4'>;
  readonly count: UniformNode<'int', number>;
}

/** One bin's wavelengths: its ends and centre, and its weight. */
export interface Bin {
  readonly index: Node<'int'>;
  readonly low: FloatNode;
  readonly high: FloatNode;
  readonly center: FloatNode;
}

/**
 * Σ over the visited bins of `reflectance(bin)` × the bin's weight; under a line source, Σ over its
 * lines instead, each a bin of no width [λ, λ] (its phase window none) in the bin it falls in (whose
 * index a stack's texture reads) times the line's weight, as binnedIntegration.glsl sums them. In
 * `planes` colour planes (3: the columns of the film's environment matrix, each bin's R once for
 * all three, each with its own weights: src/film/spectralBinsTexture.ts's rows and lines). One
 * loop serves bins and lines, the step's wavelengths and weights chosen at its start, so that the
 * graph holds `reflectance` once: three builds a program in time proportional to its graph.
 */
export function binSumPlanes(
  bins: SpectralBinNodes,
  lines: LightLineNodes,
  reflectance: (bin: Bin) => FloatNode,
  planes: PlaneCount,
): Node<'vec3'>[] {
  const width = (LAMBDA_MAX_NM - LAMBDA_MIN_NM) / bins.count;
  const sums = Array.from({ length: planes }, () => vec3(0, 0, 0).toVar());
  // Plane p's weights row (spectralBinsTexture.ts's weightsRow) and its first line, or bins.plane's.
  const planeOf = (p: number): Node<'int'> => (planes === 1 && bins.plane ? bins.plane : int(p));
  const row = (p: number) => (planes === 1 && bins.plane ? select(bins.plane.equal(0), int(0), bins.plane.add(1)) : int(weightsRow(p)));
  const byLines = lines.count.greaterThan(0);
  const start = select(byLines, int(0), int(bins.first));
  const end = select(byLines, lines.count, int(bins.end));
  Loop({ start, end, type: 'int', condition: '<' }, ({ i }: { i: Node<'int'> }) => {
    const low = float(0).toVar();
    const high = float(0).toVar();
    const index = int(0).toVar();
    If(byLines, () => {
      const nm = lines.values.element(i).w;
      low.assign(nm);
      high.assign(nm);
      index.assign(int(clamp(nm.sub(LAMBDA_MIN_NM).div(width), 0, bins.count - 1)));
    }).Else(() => {
      low.assign(float(i).mul(width).add(LAMBDA_MIN_NM));
      high.assign(low.add(width));
      index.assign(i);
    });
    const r = reflectance({ index, low, high, center: low.add(high).mul(0.5) }).toVar();
    sums.forEach((sum, p) => {
      const weight = vec3(0, 0, 0).toVar();
      If(byLines, () => {
        weight.assign(lines.values.element(i.add(planeOf(p).mul(MAX_LIGHT_LINES))).xyz);
      }).Else(() => {
        weight.assign(textureLoad(bins.weights, ivec2(i, row(p))).xyz);
      });
      sum.addAssign(weight.mul(r));
    });
  });
  return sums;
}

/** binSumPlanes in one plane: the film's XYZ under the light. */
export const binSum = (bins: SpectralBinNodes, lines: LightLineNodes, reflectance: (bin: Bin) => FloatNode): Node<'vec3'> =>
  binSumPlanes(bins, lines, reflectance, 1)[0]!;

/**
 * R of one bin: the closed-form mean over its phase window [phase − halfWidth, phase + halfWidth],
 * an absorbing film's attenuation at the bin's centre folded into t_ab t_ba r_bc and r_ba r_bc; R at
 * its centre for an evanescent film (Re Δ = 0: no fringes to average).
 */
export function binReflectance(o: FilmOptics, centerNm: FloatNode, phase: FloatNode, halfWidth: FloatNode): FloatNode {
  const path = o.opticalPathNm;
  const a = roundTripAttenuation(path, centerNm).toVar();
  const attenuated = (c: AiryTerms): AiryTerms => ({ rab: c.rab, multiple: c.multiple.mul(a), roundTrip: c.roundTrip.mul(a) });
  const mean = channelSum(o, (c) => meanChannelReflectance(attenuated(c), phase, halfWidth));
  return select(path.x.equal(0).and(path.y.notEqual(0)), reflectanceAt(o, centerNm), mean);
}

/**
 * The bins of a film whose media are the same at every λ: each bin's phase window from the optical
 * path at its ends, widened (in quadrature) by extraHalfWidthPerInvNm × (nm / λ), which the table
 * pass uses to average over a cell's thickness range.
 */
export function binnedXyz(
  bins: SpectralBinNodes,
  lines: LightLineNodes,
  o: FilmOptics,
  extraHalfWidthPerInvNm: FloatNode = float(0),
  planes: PlaneCount = 1,
): Node<'vec3'>[] {
  const path = o.opticalPathNm;
  return binSumPlanes(
    bins,
    lines,
    ({ low, high, center }) => {
      const inverseLow = float(1).div(low);
      const inverseHigh = float(1).div(high);
      const phase = path.x.mul(Math.PI).mul(inverseLow.add(inverseHigh));
      const binHalf = path.x.mul(Math.PI).mul(inverseLow.sub(inverseHigh));
      const extra = extraHalfWidthPerInvNm.mul(2).div(low.add(high));
      return binReflectance(o, center, phase, length(vec2(binHalf, extra)));
    },
    planes,
  );
}

/**
 * Film reflectance in TSL by the Airy sum, eqs (1)–(14), and its closed-form mean over a phase
 * window. The node twin of shaders/physics/filmReflectance.glsl (src/physics/filmReflectance.ts);
 * the channels are unrolled here, each R weighted by a node (a constant where the polarisation is
 * the program's, a uniform where the table's fill takes s and p in one program).
 */
import { If, Loop, abs, atan, atanh, clamp, cos, exp, float, int, min, select, sin, sqrt, vec2 } from 'three/tsl';
import { type Node } from 'three/webgpu';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type ComplexNode, type FloatNode, cAbs2, cDiv, cExpI, cIsZero, cMul } from './complex.ts';
import { type InterfaceCoefficients, fresnelCoefficients, interfaceBothWays } from './fresnel.ts';
import { shaderFunction } from './shaderFunction.ts';
import { refractedCos } from './snell.ts';

/** A channel's kind: 0 = s, 1 = p, 2 = the paper's average of the amplitudes (eqs 4, 8). */
export type ChannelKind = 0 | 1 | 2;

/** The channels whose R is averaged, for each polarisation. */
export const CHANNEL_KINDS: Readonly<Record<Polarization, readonly ChannelKind[]>> = { unpolarized: [0, 1], paper: [2], s: [0], p: [1] };

/** The channels a film's R is the weighted sum of: their kinds, and each one's weight (the weights sum to 1). */
export interface Channels {
  readonly kinds: readonly ChannelKind[];
  readonly weights: readonly FloatNode[];
}

/** A polarisation's weight of each of `kinds`: 1/n for its n channels, 0 for the others. */
export const channelWeights = (p: Polarization, kinds: readonly ChannelKind[]): number[] =>
  kinds.map((k) => (CHANNEL_KINDS[p].includes(k) ? 1 / CHANNEL_KINDS[p].length : 0));

/** A polarisation's channels in a program of its own: its kinds, each of equal, constant weight. */
export const channelsOf = (p: Polarization): Channels => ({
  kinds: CHANNEL_KINDS[p],
  weights: channelWeights(p, CHANNEL_KINDS[p]).map((w) => float(w)),
});

/** Σ weight × R over the channels. */
export const weightedSum = (weights: readonly FloatNode[], values: readonly FloatNode[]): FloatNode =>
  values.map((v, i) => v.mul(weights[i]!)).reduce((a, b) => a.add(b));

/** The λ-independent factors of eq (13) for one channel: r = r_ab + multiple e^{iφ} / (1 − roundTrip e^{iφ}). */
export interface AiryTerms {
  readonly rab: ComplexNode;
  readonly multiple: ComplexNode;
  readonly roundTrip: ComplexNode;
}

export interface FilmOptics {
  readonly channels: readonly AiryTerms[];
  /** each channel's weight in R */
  readonly weights: readonly FloatNode[];
  /** Δ = 2 ñ_b d cos θ_r (eq 12 reduced) */
  readonly opticalPathNm: ComplexNode;
}

/**
 * Σ weight × `each(channel)` over the film's channels, in a loop whose step picks its channel's
 * terms, so that the graph holds `each` once (three builds a program in time proportional to its
 * graph); one channel is `each` of it alone.
 */
export function channelSum(o: Pick<FilmOptics, 'channels' | 'weights'>, each: (c: AiryTerms) => FloatNode): FloatNode {
  const [first, ...rest] = o.channels;
  if (rest.length === 0) return each(first!).mul(o.weights[0]!);
  const sum = float(0).toVar();
  Loop(o.channels.length, ({ i }: { i: Node<'int'> }) => {
    const pick = <T extends Node>(of: (k: number) => T): T =>
      rest.reduce<T>((picked, _, k) => select(i.equal(int(k + 1)), of(k + 1), picked) as T, of(0));
    const c = {
      rab: pick((k) => o.channels[k]!.rab),
      multiple: pick((k) => o.channels[k]!.multiple),
      roundTrip: pick((k) => o.channels[k]!.roundTrip),
    };
    sum.addAssign(each(c).mul(pick((k) => o.weights[k]!)));
  });
  return sum;
}

/** (r, t) of one interface for a channel kind. */
export function channelOf(c: InterfaceCoefficients, kind: ChannelKind): { readonly r: ComplexNode; readonly t: ComplexNode } {
  if (kind === 0) return { r: c.rs, t: c.ts };
  if (kind === 1) return { r: c.rp, t: c.tp };
  return { r: c.rs.add(c.rp).mul(0.5), t: c.ts.add(c.tp).mul(0.5) };
}

/** Re Δ per nm of thickness for light from n_a: Re(2 ñ_b cos θ_r) (eq 12 reduced), 0 for an evanescent film. */
export const filmPathPerNm = (nFilm: ComplexNode, nOutside: FloatNode, cosIncidence: FloatNode): FloatNode =>
  cMul(nFilm, refractedCos(nFilm, nOutside, cosIncidence)).x.mul(2);

/**
 * The film's optics; the outside transparent (real n_a), the film and the inside ñ = vec2(n, k). At
 * d = 0 the physical channels are the bare a|c interface, eq (13)'s own value there; the paper's
 * channel keeps eq (13).
 */
export function filmOptics(
  { kinds, weights }: Channels,
  nOutside: FloatNode,
  nFilm: ComplexNode,
  nInside: ComplexNode,
  thicknessNm: FloatNode,
  cosIncidence: FloatNode,
): FilmOptics {
  const na = vec2(nOutside, 0);
  const cosI = refractedCos(na, nOutside, cosIncidence).toVar();
  const cosR = refractedCos(nFilm, nOutside, cosIncidence).toVar();
  const cosT = refractedCos(nInside, nOutside, cosIncidence).toVar();
  const { forward: ab, backward: ba } = interfaceBothWays(na, cosI, nFilm, cosR);
  const bc = fresnelCoefficients(nFilm, cosR, nInside, cosT);
  const ac = fresnelCoefficients(na, cosI, nInside, cosT);
  const bare = thicknessNm.equal(0);
  const channels = kinds.map((kind): AiryTerms => {
    const [a, b, c] = [channelOf(ab, kind), channelOf(ba, kind), channelOf(bc, kind)];
    const film = { rab: a.r, multiple: cMul(cMul(a.t, b.t), c.r), roundTrip: cMul(b.r, c.r) };
    if (kind === 2) return film;
    const zero = vec2(0, 0);
    return {
      rab: select(bare, channelOf(ac, kind).r, film.rab).toVar(),
      multiple: select(bare, zero, film.multiple).toVar(),
      roundTrip: select(bare, zero, film.roundTrip).toVar(),
    };
  });
  return { channels, weights, opticalPathNm: cMul(nFilm, cosR).mul(thicknessNm.mul(2)).toVar() };
}

/** A channel's Airy terms as a function's parameters, and back. */
const AIRY_TERMS = [
  ['rab', 'vec2'],
  ['multiple', 'vec2'],
  ['roundTrip', 'vec2'],
] as const;

/** One channel's R, eq (13) squared, at the round-trip phase factor z = e^{iφ}. */
const channelReflectanceFn = shaderFunction('tfcChannelR', 'float', [...AIRY_TERMS, ['z', 'vec2']], (rab, multiple, roundTrip, z) => {
  const series = cDiv(cMul(multiple, z), vec2(1, 0).sub(cMul(roundTrip, z)));
  return cAbs2(rab.add(select(cIsZero(multiple), vec2(0, 0), series)));
});

/** One channel's R, eq (13) squared, at the round-trip phase factor z = e^{iφ}. */
export const channelReflectance = (c: AiryTerms, z: ComplexNode): FloatNode => channelReflectanceFn(c.rab, c.multiple, c.roundTrip, z);

/** R at one wavelength, eqs (11), (13), (14), the channels' weighted sum. */
export function reflectanceAt(o: FilmOptics, lambdaNm: FloatNode): FloatNode {
  const z = cExpI(o.opticalPathNm.mul(float(2 * Math.PI).div(lambdaNm))).toVar();
  return min(
    1,
    channelSum(o, (c) => channelReflectance(c, z)),
  );
}

/**
 * The mean of one channel's R over phases [φ0 − w, φ0 + w] in closed form (meanChannelReflectance
 * in src/physics/filmReflectance.ts derives it), with the GLSL twin's float32 guard: a window
 * narrower than the resonance (w < (1 − ρ)/2) averaged by Simpson's rule on eq (13) itself
 * (docs/gpu.md#float32-limits).
 */
const meanChannelReflectanceFn = shaderFunction(
  'tfcMeanChannelR',
  'float',
  [...AIRY_TERMS, ['phaseCenter', 'float'], ['halfWidth', 'float']],
  (rab, multiple, roundTrip, phaseCenter, w) => {
    const c = { rab, multiple, roundTrip };
    const alpha = rab;
    const beta = multiple.sub(cMul(rab, roundTrip));
    const a0 = cAbs2(alpha).add(cAbs2(beta)).toVar();
    const ab = cMul(vec2(alpha.x, alpha.y.negate()), beta).toVar();
    const rho2 = cAbs2(roundTrip).toVar();
    const sinc = select(w.equal(0), float(1), sin(w).div(w)).toVar();
    const mean = float(0).toVar();
    If(cIsZero(multiple), () => {
      mean.assign(cAbs2(alpha));
    })
      .ElseIf(rho2.equal(0), () => {
        mean.assign(a0.add(sinc.mul(2).mul(ab.x.mul(cos(phaseCenter)).sub(ab.y.mul(sin(phaseCenter))))));
      })
      .ElseIf(w.lessThan(float(1).sub(sqrt(rho2)).mul(0.5)), () => {
        // Simpson's weights 1, 4, 1 at φ0 − w, φ0, φ0 + w, in a loop: eq (13) once in the function.
        const sum = float(0).toVar();
        Loop(3, ({ i }: { i: Node<'int'> }) => {
          const phase = phaseCenter.add(w.mul(float(i.sub(1))));
          sum.addAssign(channelReflectance(c, cExpI(vec2(phase, 0))).mul(select(i.equal(1), float(4), float(1))));
        });
        mean.assign(clamp(sum.div(6), 0, 1));
      })
      .Else(() => {
        mean.assign(resonantMean(c, { a0, ab, rho2, sinc }, phaseCenter, w));
      });
    return mean;
  },
);

/** The mean of one channel's R over phases [φ0 − w, φ0 + w] (meanChannelReflectanceFn). */
export const meanChannelReflectance = (c: AiryTerms, phaseCenter: FloatNode, halfWidth: FloatNode): FloatNode =>
  meanChannelReflectanceFn(c.rab, c.multiple, c.roundTrip, phaseCenter, halfWidth);

/** The closed form of meanChannelReflectance away from d = 0 and outside the narrow-window guard. */
function resonantMean(
  c: AiryTerms,
  t: { readonly a0: FloatNode; readonly ab: ComplexNode; readonly rho2: FloatNode; readonly sinc: FloatNode },
  phaseCenter: FloatNode,
  w: FloatNode,
): FloatNode {
  const { a0, ab, rho2, sinc } = t;
  const rho = sqrt(rho2);
  // arg(c), with Im c = −0.0 read as 0 (docs/gpu.md#signed-zero-in-atan).
  const rt = c.roundTrip;
  const gamma = select(rt.y.equal(0), select(rt.x.lessThan(0), float(Math.PI), float(0)), atan(rt.y, rt.x));
  const psi0 = phaseCenter.add(gamma).toVar();
  const u = cDiv(ab, rt).toVar();
  const cosW = cos(w);
  const cos0 = cos(psi0);
  const y = rho
    .mul(2)
    .mul(sinc)
    .mul(cos0.sub(rho.mul(cosW)));
  const x = float(1)
    .sub(rho.mul(2).mul(cos0).mul(cosW))
    .add(rho2.mul(cos(w.mul(2))));
  const dA = select(w.lessThan(1e-4), y.div(x), atan(y.mul(w), x).div(w)).toVar();
  const dPlus = rho2.add(1).sub(rho.mul(2).mul(cos(psi0.add(w))));
  const dMinus = rho2.add(1).sub(rho.mul(2).mul(cos(psi0.sub(w))));
  const qOverW = rho.mul(4).mul(sin(psi0)).mul(sinc).div(dPlus.add(dMinus)).toVar();
  const q = qOverW.mul(w).toVar();
  // Below |q| = 1e-3, atanh(q)/q = 1 + q²/3 to 2e-13, as in the TypeScript twin.
  const L = select(abs(q).lessThan(1e-3), qOverW.mul(q.mul(q).div(3).add(1)), atanh(q).div(q).mul(qOverW));
  const mean = a0
    .mul(dA.add(1))
    .add(u.x.mul(rho2.mul(2).add(rho2.add(1).mul(dA))))
    .div(float(1).sub(rho2))
    .sub(u.y.mul(L));
  return clamp(mean, 0, 1);
}

/** exp(−2π Im Δ / λ): an absorbing film's attenuation of one round trip at λ. */
export const roundTripAttenuation = (opticalPathNm: ComplexNode, lambdaNm: FloatNode): FloatNode =>
  exp(opticalPathNm.y.mul(-2 * Math.PI).div(lambdaNm));

import { cScale, cTimesIndex } from './complex.ts';
import {
  type AiryTerms,
  type FilmOptics,
  type FilmStack,
  type Polarization,
  filmOptics,
  meanChannelReflectance,
  reflectanceAt,
} from './filmReflectance.ts';
import { type Medium, isDispersiveMedium, mediumIndexAt, mediumStackAt, transparentIndexAt } from './medium.ts';
import { cosDeg, refractedCos } from './snell.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM } from './spectralConventions.ts';
import type { SpectralWeights, WeightedLine, Xyz } from './spectralWeights.ts';

/**
 * The shader's integration (mirrored by `shaders/physics/binnedIntegration.glsl`): `count` equal
 * wavelength bins over 380–830 nm, each holding ∫_bin I_in x̄, ȳ, z̄ dλ / k (exact for the
 * piecewise-linear 1 nm weights), so X = Σ_bins W_bin · R̄_bin with R̄_bin the closed-form mean of
 * R over the bin's phase window (`meanChannelReflectance`). Fringes narrower than a bin average
 * out instead of aliasing. `count` must divide 450 so bins end on 1 nm knots.
 *
 * The phase φ = 2πΔσ is linear in the wavenumber σ = 1/λ, so a film of constant path sees, over a
 * bin, the light's distribution of σ there. Each bin's window is the box with that distribution's
 * mean σ̄ and variance (half-width √3 sd): a lamp's table puts most of a bin's light at one edge
 * (a mercury line tabulated in one 5 nm row), where a window over the whole bin would weigh every
 * phase alike (docs/physics.md#lights).
 */
export interface SpectralBins {
  readonly count: number;
  /** [X, Y, Z] weight of bin i at 3i..3i+2 */
  readonly weights: Float64Array;
  /** The bins integrated: first ≤ b < end (all of them unless `significantBins` trimmed the tails). */
  readonly first: number;
  readonly end: number;
  /**
   * Bin i's distribution of σ = 1/λ under the light (I_in (x̄ + ȳ + z̄) / k): at 2i its mean σ̄ less
   * the bin's middle σ, (1/λ1 + 1/λ2)/2, and at 2i + 1 the half-width √3 sd of the box with its
   * variance (that of a flat distribution in σ over the bin where the bin has no light).
   */
  readonly windows: Float64Array;
  /** A line source's lines (spectralWeights): integrated as bins of no width, R at each line; the weights above are then 0. */
  readonly lines?: readonly WeightedLine[];
}

/** The centre in nm of bin `b` of `count` equal bins over the band. */
export const binCenterNm = (b: number, count: number): number => LAMBDA_MIN_NM + (b + 0.5) * (LAMBDA_SPAN_NM / count);

export function spectralBins(w: SpectralWeights, count: number): SpectralBins {
  if (!Number.isInteger(count) || LAMBDA_SPAN_NM % count !== 0) throw new RangeError(`bins: ${count} must divide ${LAMBDA_SPAN_NM}`);
  const perBin = LAMBDA_SPAN_NM / count;
  const weights = new Float64Array(3 * count);
  for (let b = 0; b < count; b++) {
    for (let j = 0; j < perBin; j++) {
      const i = b * perBin + j; // trapezoid over [i, i + 1] nm
      [w.x, w.y, w.z].forEach((t, k) => {
        weights[3 * b + k] = (weights[3 * b + k] as number) + ((t[i] as number) + (t[i + 1] as number)) / 2;
      });
    }
  }
  return { count, weights, first: 0, end: count, windows: binWindows(w, count), ...(w.lines && { lines: w.lines }) };
}

/** Sub-steps per nm of the moments' midpoint rule: w is linear and 1/λ smooth within each 1 nm, so the rule is exact to ~1e-10. */
const MOMENT_STEPS_PER_NM = 8;

/** SpectralBins.windows: each bin's σ̄ − σ_middle and √3 sd of σ, by the midpoint rule on the 1 nm weights. */
function binWindows(w: SpectralWeights, count: number): Float64Array {
  const perBin = LAMBDA_SPAN_NM / count;
  const windows = new Float64Array(2 * count);
  for (let b = 0; b < count; b++) {
    const [l1, l2] = [LAMBDA_MIN_NM + b * perBin, LAMBDA_MIN_NM + (b + 1) * perBin];
    const middle = (1 / l1 + 1 / l2) / 2;
    let [m0, m1, m2] = [0, 0, 0];
    for (let j = 0; j < perBin * MOMENT_STEPS_PER_NM; j++) {
      const u = b * perBin + (j + 0.5) / MOMENT_STEPS_PER_NM;
      const [i, f] = [Math.floor(u), u - Math.floor(u)];
      const v = [w.x, w.y, w.z].reduce((sum, t) => sum + (t[i] as number) * (1 - f) + (t[i + 1] as number) * f, 0);
      const offset = 1 / (LAMBDA_MIN_NM + u) - middle;
      [m0, m1, m2] = [m0 + v, m1 + v * offset, m2 + v * offset * offset];
    }
    const mean = m0 > 0 ? m1 / m0 : 0;
    windows[2 * b] = mean;
    windows[2 * b + 1] = m0 > 0 ? Math.sqrt(3 * Math.max(0, m2 / m0 - mean * mean)) : (1 / l1 - 1 / l2) / 2;
  }
  return windows;
}

/**
 * The same bins without the tails where I_in x̄, ȳ, z̄ hardly matter: the longest runs of bins at
 * either end whose weights sum to at most `tolerance` × the white's X, Y and Z each. Since
 * 0 ≤ R ≤ 1, dropping them moves any colour by at most that much of the white, so a shader
 * skips them at no visible cost (with 1e-5: under 0.01 L* even for a black film, where L* is
 * most sensitive). 90 bins of D65 lose 770–830 nm, 12 of the 90 (380 nm still counts: z̄).
 */
export function significantBins(bins: SpectralBins, tolerance: number): SpectralBins {
  const w = bins.weights;
  const white = [0, 1, 2].map((k) => {
    let s = 0;
    for (let b = 0; b < bins.count; b++) s += w[3 * b + k] as number;
    return s;
  });
  const dropped = [0, 0, 0];
  const fits = (b: number) => [0, 1, 2].every((k) => (dropped[k] as number) + (w[3 * b + k] as number) <= tolerance * (white[k] as number));
  const take = (b: number) => [0, 1, 2].forEach((k) => (dropped[k] = (dropped[k] as number) + (w[3 * b + k] as number)));
  let first = 0;
  let end = bins.count;
  // Drop from whichever end has the lighter next bin, while the total stays within tolerance.
  for (;;) {
    const low =
      first < end && fits(first) ? Math.max(...[0, 1, 2].map((k) => (w[3 * first + k] as number) / (white[k] as number))) : Infinity;
    const high =
      end - 1 > first && fits(end - 1)
        ? Math.max(...[0, 1, 2].map((k) => (w[3 * (end - 1) + k] as number) / (white[k] as number)))
        : Infinity;
    if (low === Infinity && high === Infinity) break;
    if (low <= high) take(first++);
    else take(--end);
  }
  return { ...bins, first, end };
}

/** One bin as a film's window sees it: its ends in nm, and its light's σ̄ and half-width √3 sd in σ (SpectralBins.windows). */
interface BinSpan {
  readonly l1: number;
  readonly l2: number;
  readonly sigma: number;
  readonly sigmaHalf: number;
}

/** What one bin needs: the optics and λ its absorption is taken at, and its phase window [center − half, center + half]. */
interface BinWindow {
  readonly optics: FilmOptics;
  readonly centerNm: number;
  readonly phaseCenter: number;
  readonly halfWidth: number;
}

/**
 * A channel at a bin's centre λ with the film's absorption folded in: an absorbing film's phase
 * φ = 2πΔ/λ has Im φ > 0, so e^{iφ} = a e^{i Re φ} with a = e^{−Im φ}, and eq (13) reads the same
 * with t_ab t_ba r_bc and r_ba r_bc scaled by a (docs/physics.md#absorbing-media). a is taken at the
 * centre; over a bin it changes by a fraction of Im φ's change, and the closed-form mean covers Re φ.
 */
const attenuated = (c: AiryTerms, a: number): AiryTerms => ({ ...c, multiple: cScale(c.multiple, a), roundTrip: cScale(c.roundTrip, a) });

/**
 * R̄ of one bin: the closed-form mean over its phase window [center − half, center + half] of the
 * real phase, the film's absorption at the bin's centre folded in (`attenuated`); R at the centre
 * for an evanescent film (a real film past the critical angle: Re Δ = 0, no fringes to average).
 */
export function binReflectance(optics: FilmOptics, centerNm: number, phaseCenter: number, halfWidth: number): number {
  const path = optics.opticalPathNm;
  if (path.re === 0 && path.im !== 0) return reflectanceAt(optics, centerNm);
  const a = path.im === 0 ? 1 : Math.exp((-2 * Math.PI * path.im) / centerNm);
  let r = 0;
  for (const c of optics.channels) r += meanChannelReflectance(a === 1 ? c : attenuated(c, a), phaseCenter, halfWidth);
  return r / optics.channels.length;
}

/**
 * X = Σ W_bin R̄_bin (binReflectance) over each bin's window. A line source's lines are bins of no
 * width [λ_l, λ_l], σ̄ = 1/λ_l and no spread: R at the line (docs/physics.md#lights).
 */
function binsXyz(bins: SpectralBins, windowOf: (span: BinSpan) => BinWindow): Xyz {
  const width = LAMBDA_SPAN_NM / bins.count;
  const lines = bins.lines;
  const xyz = [0, 0, 0];
  for (let i = 0, n = lines ? lines.length : bins.end - bins.first; i < n; i++) {
    const line = lines?.[i];
    const b = bins.first + i;
    const l1 = line ? line.nm : LAMBDA_MIN_NM + b * width;
    const l2 = line ? line.nm : l1 + width;
    const sigma = (1 / l1 + 1 / l2) / 2 + (line ? 0 : (bins.windows[2 * b] as number));
    const weights = line ? [line.x, line.y, line.z] : [0, 1, 2].map((k) => bins.weights[3 * b + k] as number);
    const { optics, centerNm, phaseCenter, halfWidth } = windowOf({
      l1,
      l2,
      sigma,
      sigmaHalf: line ? 0 : (bins.windows[2 * b + 1] as number),
    });
    const r = binReflectance(optics, centerNm, phaseCenter, halfWidth);
    for (let k = 0; k < 3; k++) xyz[k] = (xyz[k] as number) + r * (weights[k] as number);
  }
  return [xyz[0] as number, xyz[1] as number, xyz[2] as number];
}

/**
 * XYZ by bins, as the shader computes it: each bin's window φ = 2π Re Δ σ over its light's σ̄ ± √3 sd.
 * `extraHalfWidthPerInvNm` widens every window by that many radians × (nm/λ) at σ̄, in quadrature
 * (variances of box filters add): the table pass uses it to average over a table cell's thickness
 * range, 2π · 2 n_b cos θ_r · (δd/2) / λ.
 */
export function binnedXyz(optics: FilmOptics, bins: SpectralBins, extraHalfWidthPerInvNm = 0): Xyz {
  const path = optics.opticalPathNm.re;
  return binsXyz(bins, ({ sigma, sigmaHalf }) => ({
    optics,
    centerNm: 1 / sigma,
    phaseCenter: 2 * Math.PI * path * sigma,
    halfWidth: Math.hypot(2 * Math.PI * path * sigmaHalf, extraHalfWidthPerInvNm * sigma),
  }));
}

/** Re Δ per nm of thickness at λ: Re(2 ñ_b cos θ_r), eq (12) reduced (filmOptics' Δ of a 1 nm film). */
export function pathPerNmAt(stack: Omit<FilmStack<Medium>, 'thicknessNm'>, lambdaNm: number): number {
  const nb = mediumIndexAt(stack.nFilm, lambdaNm);
  const na = transparentIndexAt(stack.nOutside, lambdaNm);
  return 2 * cTimesIndex(refractedCos(nb, na, cosDeg(stack.angleDeg)), nb).re;
}

/**
 * XYZ by bins of a film whose media depend on λ (shaders/physics/binnedIntegration.glsl, dispersiveBinnedXyz):
 * each bin's Fresnel terms at ñ of its centre, its phase 2π Re Δ(λ)/λ with Δ(λ) = 2 ñ_b(λ) d cos θ_r(λ)
 * taken at its two ends and as linear in σ between them, over its light's window in σ (as
 * binnedXyz's), the film's absorption as binReflectance folds it.
 */
export function dispersiveBinnedXyz(stack: FilmStack<Medium>, polarization: Polarization, bins: SpectralBins): Xyz {
  return binsXyz(bins, ({ l1, l2, sigma, sigmaHalf }) => {
    // φ = 2π Re Δ(λ) σ at the two ends, taken as linear in σ between them.
    const [low, high] = [(pathPerNmAt(stack, l1) * stack.thicknessNm) / l1, (pathPerNmAt(stack, l2) * stack.thicknessNm) / l2];
    const slope = l1 === l2 ? 0 : (2 * Math.PI * (low - high)) / (1 / l1 - 1 / l2);
    return {
      optics: filmOptics(mediumStackAt(stack, (l1 + l2) / 2), polarization),
      centerNm: (l1 + l2) / 2,
      phaseCenter: Math.PI * (low + high) + slope * (sigma - (1 / l1 + 1 / l2) / 2),
      halfWidth: Math.abs(slope) * sigmaHalf,
    };
  });
}

/** Whether a stack's bins need ñ per bin (a medium that depends on λ), not one set of optics. */
export const isDispersiveStack = (stack: Pick<FilmStack<Medium>, 'nOutside' | 'nFilm' | 'nInside'>): boolean =>
  [stack.nOutside, stack.nFilm, stack.nInside].some(isDispersiveMedium);

/** XYZ by bins of any film: binnedXyz of its optics for constant media (real or complex), dispersiveBinnedXyz otherwise. */
export const stackBinnedXyz = (stack: FilmStack<Medium>, polarization: Polarization, bins: SpectralBins): Xyz =>
  isDispersiveStack(stack)
    ? dispersiveBinnedXyz(stack, polarization, bins)
    : binnedXyz(filmOptics(mediumStackAt(stack, LAMBDA_MIN_NM), polarization), bins);

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
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM, type SpectralWeights, type WeightedLine, type Xyz } from './spectralWeights.ts';

/**
 * The shader's integration (mirrored by `shaders/physics/binnedIntegration.glsl`): `count` equal
 * wavelength bins over 380–830 nm, each holding ∫_bin I_in x̄, ȳ, z̄ dλ / k (exact for the
 * piecewise-linear 1 nm weights), so X = Σ_bins W_bin · R̄_bin with R̄_bin the closed-form mean of
 * R over the bin's phase window (`meanChannelReflectance`). Fringes narrower than a bin average
 * out instead of aliasing. `count` must divide 450 so bins end on 1 nm knots.
 */
export interface SpectralBins {
  readonly count: number;
  /** [X, Y, Z] weight of bin i at 3i..3i+2 */
  readonly weights: Float64Array;
  /** The bins integrated: first ≤ b < end (all of them unless `significantBins` trimmed the tails). */
  readonly first: number;
  readonly end: number;
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
  return { count, weights, first: 0, end: count, ...(w.lines && { lines: w.lines }) };
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

/** What one bin needs: the optics at its centre, and the real optical path at its two ends. */
interface BinFilm {
  readonly optics: FilmOptics;
  readonly pathLowNm: number;
  readonly pathHighNm: number;
  /** The extra phase half-width at the bin's centre (a table cell's thickness range), radians. */
  readonly extraHalfWidth: number;
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
 * X = Σ W_bin R̄_bin (binReflectance), each bin's phase window widened in quadrature by its extra
 * half-width. A line source's lines are bins of no width [λ_l, λ_l]: R at the line, averaged over
 * the extra half-width only (docs/physics.md#lights).
 */
function binsXyz(bins: SpectralBins, binFilm: (l1: number, l2: number) => BinFilm): Xyz {
  const width = LAMBDA_SPAN_NM / bins.count;
  const lines = bins.lines;
  const xyz = [0, 0, 0];
  for (let i = 0, n = lines ? lines.length : bins.end - bins.first; i < n; i++) {
    const line = lines?.[i];
    const b = bins.first + i;
    const l1 = line ? line.nm : LAMBDA_MIN_NM + b * width;
    const l2 = line ? line.nm : l1 + width;
    const weights = line ? [line.x, line.y, line.z] : [0, 1, 2].map((k) => bins.weights[3 * b + k] as number);
    const { optics, pathLowNm, pathHighNm, extraHalfWidth } = binFilm(l1, l2);
    const center = Math.PI * (pathLowNm / l1 + pathHighNm / l2);
    const binHalf = Math.PI * (pathLowNm / l1 - pathHighNm / l2);
    const r = binReflectance(optics, (l1 + l2) / 2, center, Math.hypot(binHalf, extraHalfWidth));
    for (let k = 0; k < 3; k++) xyz[k] = (xyz[k] as number) + r * (weights[k] as number);
  }
  return [xyz[0] as number, xyz[1] as number, xyz[2] as number];
}

/**
 * XYZ by bins, as the shader computes it. `extraHalfWidthPerInvNm` widens every bin's phase
 * window by that many radians × (nm/λ), in quadrature (variances of box filters add): the table
 * pass uses it to average over a table cell's thickness range, 2π · 2 n_b cos θ_r · (δd/2) / λ.
 */
export function binnedXyz(optics: FilmOptics, bins: SpectralBins, extraHalfWidthPerInvNm = 0): Xyz {
  const path = optics.opticalPathNm.re;
  return binsXyz(bins, (l1, l2) => ({
    optics,
    pathLowNm: path,
    pathHighNm: path,
    extraHalfWidth: (2 * extraHalfWidthPerInvNm) / (l1 + l2),
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
 * each bin's Fresnel terms at ñ of its centre, its phase window from the optical path at its two
 * ends, 2π Re Δ(λ)/λ with Δ(λ) = 2 ñ_b(λ) d cos θ_r(λ), the film's absorption as binReflectance folds it.
 */
export function dispersiveBinnedXyz(stack: FilmStack<Medium>, polarization: Polarization, bins: SpectralBins): Xyz {
  return binsXyz(bins, (l1, l2) => ({
    optics: filmOptics(mediumStackAt(stack, (l1 + l2) / 2), polarization),
    pathLowNm: pathPerNmAt(stack, l1) * stack.thicknessNm,
    pathHighNm: pathPerNmAt(stack, l2) * stack.thicknessNm,
    extraHalfWidth: 0,
  }));
}

/** Whether a stack's bins need ñ per bin (a medium that depends on λ), not one set of optics. */
export const isDispersiveStack = (stack: Pick<FilmStack<Medium>, 'nOutside' | 'nFilm' | 'nInside'>): boolean =>
  [stack.nOutside, stack.nFilm, stack.nInside].some(isDispersiveMedium);

/** XYZ by bins of any film: binnedXyz of its optics for constant media (real or complex), dispersiveBinnedXyz otherwise. */
export const stackBinnedXyz = (stack: FilmStack<Medium>, polarization: Polarization, bins: SpectralBins): Xyz =>
  isDispersiveStack(stack)
    ? dispersiveBinnedXyz(stack, polarization, bins)
    : binnedXyz(filmOptics(mediumStackAt(stack, LAMBDA_MIN_NM), polarization), bins);

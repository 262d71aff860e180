import { CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, CIE1931_XBAR, CIE1931_YBAR, CIE1931_ZBAR } from './data/cie1931Cmf2deg.ts';
import { type FilmOptics, type FilmStack, type Polarization, filmOptics, meanChannelReflectance, reflectanceAt } from './filmReflectance.ts';
import { type IlluminantSpec, illuminantKey, illuminantSpd, interpolateTable } from './illuminants.ts';

/** The integration range of eqs (16)–(18). */
export const LAMBDA_MIN_NM = 380;
export const LAMBDA_MAX_NM = 830;
const SPAN_NM = LAMBDA_MAX_NM - LAMBDA_MIN_NM;

/**
 * Normalisation of eqs (16)–(18):
 * - `white`: k = ∫ I_in ȳ dλ, so a perfect white reflector has Y = 1 (default);
 * - `paper`: the paper's k = ∫ ȳ dλ, with I_in scaled to 1 at 560 nm.
 */
export const NORMALIZATIONS = ['white', 'paper'] as const;
export type Normalization = (typeof NORMALIZATIONS)[number];

export type Xyz = readonly [number, number, number];

/**
 * I_in(λ)·x̄, ȳ, z̄(λ) / k at every 1 nm from 380 to 830 nm (451 knots; between knots the
 * weights are linear). These are the tables the shader receives as a texture.
 */
export interface SpectralWeights {
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly z: Float64Array;
}

const weightsCache = new Map<string, SpectralWeights>();
/** Weights kept (11 kB each): a CCT slider dragged for an hour must not grow the cache without end. */
const MAX_CACHED_WEIGHTS = 64;

/** The weights of eqs (15)–(18) for an illuminant and normalisation (the last 64 used are cached). */
export function spectralWeights(illuminant: IlluminantSpec, normalization: Normalization = 'white'): SpectralWeights {
  const key = `${illuminantKey(illuminant)}|${normalization}`;
  const cached = weightsCache.get(key);
  if (cached) {
    weightsCache.delete(key); // most recently used last
    weightsCache.set(key, cached);
    return cached;
  }
  const spd = illuminantSpd(illuminant);
  const n = SPAN_NM + 1;
  const cmf = (t: readonly number[], l: number) => interpolateTable(t, CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, l);
  const x = new Float64Array(n);
  const y = new Float64Array(n);
  const z = new Float64Array(n);
  const scale = normalization === 'paper' ? 1 / spd(560) : 1;
  for (let i = 0; i < n; i++) {
    const l = LAMBDA_MIN_NM + i;
    const s = spd(l) * scale;
    x[i] = s * cmf(CIE1931_XBAR, l);
    y[i] = s * cmf(CIE1931_YBAR, l);
    z[i] = s * cmf(CIE1931_ZBAR, l);
  }
  // k by the same trapezoid rule as the colour integral, so a perfect reflector gives Y = 1 exactly.
  const k = normalization === 'paper' ? trapezoid1nm((l) => cmf(CIE1931_YBAR, l)) : trapezoid1nm((_, i) => y[i] as number);
  for (const t of [x, y, z]) for (let i = 0; i < n; i++) t[i] = (t[i] as number) / k;
  const w = { x, y, z };
  weightsCache.set(key, w);
  if (weightsCache.size > MAX_CACHED_WEIGHTS) weightsCache.delete(weightsCache.keys().next().value!);
  return w;
}

function trapezoid1nm(f: (lambdaNm: number, i: number) => number): number {
  let sum = 0;
  for (let i = 0; i <= SPAN_NM; i++) sum += f(LAMBDA_MIN_NM + i, i) * (i === 0 || i === SPAN_NM ? 0.5 : 1);
  return sum;
}

/**
 * ∫ R(λ) W(λ) dλ over 380–830 nm for the three weight tables, by the trapezoid rule with
 * `stepsPerNm` equal sub-steps in every 1 nm interval. The 1 nm knots of W are nodes, so W is
 * exactly linear between nodes and the only error is R's variation between samples.
 */
export function integrateXyz(reflectance: (lambdaNm: number) => number, w: SpectralWeights, stepsPerNm: number): Xyz {
  const h = 1 / stepsPerNm;
  let X = 0;
  let Y = 0;
  let Z = 0;
  for (let i = 0; i < SPAN_NM; i++) {
    const x0 = w.x[i] as number, x1 = w.x[i + 1] as number;
    const y0 = w.y[i] as number, y1 = w.y[i + 1] as number;
    const z0 = w.z[i] as number, z1 = w.z[i + 1] as number;
    for (let j = i === 0 ? 0 : 1; j <= stepsPerNm; j++) {
      const f = j * h;
      const r = reflectance(LAMBDA_MIN_NM + i + f) * (j === 0 || (j === stepsPerNm && i === SPAN_NM - 1) ? 0.5 : 1);
      X += r * (x0 + (x1 - x0) * f);
      Y += r * (y0 + (y1 - y0) * f);
      Z += r * (z0 + (z1 - z0) * f);
    }
  }
  return [X * h, Y * h, Z * h];
}

/**
 * Sampling that converges at every thickness (docs/physics.md#sampling). R(λ) is periodic in the phase φ
 * with one fringe per 2π, and a fringe spans about λ²/Δ nm, narrowest at 380 nm. The trapezoid
 * rule on a periodic analytic function converges geometrically with the number of samples per
 * period, at a rate set by how close eq (13)'s pole 1/(r_ba r_bc) is to the unit circle, so:
 *   samples per fringe K = max(MIN_SAMPLES_PER_FRINGE, FINESSE_SAMPLES / (1 − |r_ba r_bc|)),
 *   sub-steps per nm     = max(1, ⌈K · Re Δ / 380²⌉).
 * Cost: 451 R evaluations (×2 polarisations when unpolarised) up to Re Δ ≈ 18 000 nm (a soap
 * film 6.8 µm thick at normal incidence), then growing linearly with Δ: about 2 700 for
 * n_b = 2.5, d = 20 µm, 0°; high-finesse films near grazing incidence take more.
 */
export const MIN_SAMPLES_PER_FRINGE = 8;
export const FINESSE_SAMPLES = 4;
/** Caps the cost where |r_ba r_bc| → 1 (near grazing); the fringes there are needle-thin dips. */
export const MAX_SAMPLES_PER_FRINGE = 2000;

export function adaptiveStepsPerNm(optics: FilmOptics): number {
  const pathNm = Math.abs(optics.opticalPathNm.re);
  if (pathNm === 0) return 1;
  const rho = Math.max(...optics.channels.map((c) => Math.hypot(c.roundTrip.re, c.roundTrip.im)));
  const perFringe = Math.min(MAX_SAMPLES_PER_FRINGE, Math.max(MIN_SAMPLES_PER_FRINGE, FINESSE_SAMPLES / Math.max(1e-9, 1 - rho)));
  return Math.max(1, Math.ceil((perFringe * pathNm) / (LAMBDA_MIN_NM * LAMBDA_MIN_NM)));
}

export interface ColorOptions {
  readonly illuminant?: IlluminantSpec;
  readonly polarization?: Polarization;
  readonly normalization?: Normalization;
  /** Fixed sub-steps per nm instead of the adaptive rule (for convergence studies). */
  readonly stepsPerNm?: number;
}

/** XYZ of the light a film reflects, eqs (15)–(18). */
export function filmXyz(stack: FilmStack, options: ColorOptions = {}): Xyz {
  const optics = filmOptics(stack, options.polarization ?? 'unpolarized');
  const w = spectralWeights(options.illuminant ?? 'D65', options.normalization ?? 'white');
  return integrateXyz((l) => reflectanceAt(optics, l), w, options.stepsPerNm ?? adaptiveStepsPerNm(optics));
}

/** XYZ of the illuminant itself (a perfect white reflector), the white point for CIELAB. */
export const whiteXyz = (illuminant: IlluminantSpec, normalization: Normalization = 'white'): Xyz =>
  integrateXyz(() => 1, spectralWeights(illuminant, normalization), 1);

/**
 * The shader's integration (mirrored by `shaders/spectralIntegration.glsl`): `count` equal
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
}

export const BIN_COUNTS = [10, 15, 18, 25, 30, 45, 50, 75, 90, 150, 225, 450] as const;

export function spectralBins(w: SpectralWeights, count: number): SpectralBins {
  if (!Number.isInteger(count) || SPAN_NM % count !== 0) throw new RangeError(`bins: ${count} must divide ${SPAN_NM}`);
  const perBin = SPAN_NM / count;
  const weights = new Float64Array(3 * count);
  for (let b = 0; b < count; b++) {
    for (let j = 0; j < perBin; j++) {
      const i = b * perBin + j; // trapezoid over [i, i + 1] nm
      [w.x, w.y, w.z].forEach((t, k) => {
        weights[3 * b + k] = (weights[3 * b + k] as number) + ((t[i] as number) + (t[i + 1] as number)) / 2;
      });
    }
  }
  return { count, weights, first: 0, end: count };
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
  const white = [0, 1, 2].map((k) => { let s = 0; for (let b = 0; b < bins.count; b++) s += w[3 * b + k] as number; return s; });
  const dropped = [0, 0, 0];
  const fits = (b: number) => [0, 1, 2].every((k) => (dropped[k] as number) + (w[3 * b + k] as number) <= tolerance * (white[k] as number));
  const take = (b: number) => [0, 1, 2].forEach((k) => (dropped[k] = (dropped[k] as number) + (w[3 * b + k] as number)));
  let first = 0;
  let end = bins.count;
  // Drop from whichever end has the lighter next bin, while the total stays within tolerance.
  for (;;) {
    const low = first < end && fits(first) ? Math.max(...[0, 1, 2].map((k) => (w[3 * first + k] as number) / (white[k] as number))) : Infinity;
    const high = end - 1 > first && fits(end - 1) ? Math.max(...[0, 1, 2].map((k) => (w[3 * (end - 1) + k] as number) / (white[k] as number))) : Infinity;
    if (low === Infinity && high === Infinity) break;
    if (low <= high) take(first++);
    else take(--end);
  }
  return { ...bins, first, end };
}

/**
 * XYZ by bins, as the shader computes it. `extraHalfWidthPerInvNm` widens every bin's phase
 * window by that many radians × (nm/λ), in quadrature (variances of box filters add): the table
 * pass uses it to average over a table cell's thickness range, 2π · 2 n_b cos θ_r · (δd/2) / λ.
 */
export function binnedXyz(optics: FilmOptics, bins: SpectralBins, extraHalfWidthPerInvNm = 0): Xyz {
  const width = SPAN_NM / bins.count;
  const path = optics.opticalPathNm;
  const xyz = [0, 0, 0];
  for (let b = bins.first; b < bins.end; b++) {
    const l1 = LAMBDA_MIN_NM + b * width;
    const l2 = l1 + width;
    let r = 0;
    if (path.im !== 0) {
      r = reflectanceAt(optics, (l1 + l2) / 2); // evanescent film: no fringes to average
    } else {
      const center = Math.PI * path.re * (1 / l1 + 1 / l2);
      const binHalf = Math.PI * path.re * (1 / l1 - 1 / l2);
      const extra = (2 * extraHalfWidthPerInvNm) / (l1 + l2);
      const half = Math.hypot(binHalf, extra);
      for (const c of optics.channels) r += meanChannelReflectance(c, center, half);
      r /= optics.channels.length;
    }
    for (let k = 0; k < 3; k++) xyz[k] = (xyz[k] as number) + r * (bins.weights[3 * b + k] as number);
  }
  return [xyz[0] as number, xyz[1] as number, xyz[2] as number];
}

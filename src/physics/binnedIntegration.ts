import { type DispersiveFilmStack, filmIndexAt, stackAt } from './filmIndex.ts';
import { type FilmOptics, type Polarization, filmOptics, meanChannelReflectance, reflectanceAt } from './filmReflectance.ts';
import { cosDeg, refractedCos } from './snell.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM, type SpectralWeights, type Xyz } from './spectralWeights.ts';

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
}

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
 * X = Σ W_bin R̄_bin: R̄ the closed-form mean over the bin's phase window [2πΔ(λ2)/λ2, 2πΔ(λ1)/λ1]
 * widened in quadrature by the extra half-width, or R at the centre for an evanescent film.
 */
function binsXyz(bins: SpectralBins, binFilm: (l1: number, l2: number) => BinFilm): Xyz {
  const width = LAMBDA_SPAN_NM / bins.count;
  const xyz = [0, 0, 0];
  for (let b = bins.first; b < bins.end; b++) {
    const l1 = LAMBDA_MIN_NM + b * width;
    const l2 = l1 + width;
    const { optics, pathLowNm, pathHighNm, extraHalfWidth } = binFilm(l1, l2);
    let r = 0;
    if (optics.opticalPathNm.im !== 0) {
      r = reflectanceAt(optics, (l1 + l2) / 2); // evanescent film: no fringes to average
    } else {
      const center = Math.PI * (pathLowNm / l1 + pathHighNm / l2);
      const binHalf = Math.PI * (pathLowNm / l1 - pathHighNm / l2);
      const half = Math.hypot(binHalf, extraHalfWidth);
      for (const c of optics.channels) r += meanChannelReflectance(c, center, half);
      r /= optics.channels.length;
    }
    for (let k = 0; k < 3; k++) xyz[k] = (xyz[k] as number) + r * (bins.weights[3 * b + k] as number);
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

/**
 * XYZ by bins of a film whose index depends on λ (shaders/physics/binnedIntegration.glsl, dispersiveBinnedXyz):
 * each bin's Fresnel terms at n_b of its centre, its phase window from the optical path at its two
 * ends, 2π Δ(λ)/λ with Δ(λ) = 2 n_b(λ) d cos θ_r(λ).
 */
export function dispersiveBinnedXyz(stack: DispersiveFilmStack, polarization: Polarization, bins: SpectralBins): Xyz {
  const cos = cosDeg(stack.angleDeg);
  const pathPerNm = (l: number) => {
    const nb = filmIndexAt(stack.nFilm, l);
    return 2 * nb * refractedCos(nb, stack.nOutside, cos).re;
  };
  return binsXyz(bins, (l1, l2) => {
    const center = (l1 + l2) / 2;
    return {
      optics: filmOptics(stackAt(stack, center), polarization),
      pathLowNm: pathPerNm(l1) * stack.thicknessNm,
      pathHighNm: pathPerNm(l2) * stack.thicknessNm,
      extraHalfWidth: 0,
    };
  });
}

/** XYZ by bins of any film: binnedXyz of its optics for a constant index, dispersiveBinnedXyz otherwise. */
export const stackBinnedXyz = (stack: DispersiveFilmStack, polarization: Polarization, bins: SpectralBins): Xyz =>
  typeof stack.nFilm === 'number'
    ? binnedXyz(filmOptics({ ...stack, nFilm: stack.nFilm }, polarization), bins)
    : dispersiveBinnedXyz(stack, polarization, bins);

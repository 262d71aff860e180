import { type AirySeriesTerms, airySeriesTerms, seriesConverges, seriesXyz } from './airySeries.ts';
import { type SpectralBins, dispersiveBinnedXyz } from './binnedIntegration.ts';
import { cMul } from './complex.ts';
import { type DispersiveFilmStack, filmIndexAt, stackAt } from './filmIndex.ts';
import { type Polarization, filmOptics } from './filmReflectance.ts';
import { cosDeg, refractedCos } from './snell.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM, type SpectralWeights, type Xyz } from './spectralWeights.ts';
import { type SpectralTransform } from './spectralTransform.ts';

/**
 * The Airy series of a dispersive film (docs/physics.md#a-dispersive-film). With n_b(λ) the optical
 * path is Δ(λ) = d P(λ), P = 2 n_b(λ) cos θ_r(λ), and the phase 2πΔ/λ no longer scales as 1/λ.
 * Fitting P(λ) ≈ a + bλ over the band (least squares on the phase, weighted by the light's
 * x̄ + ȳ + z̄) makes it 2π d a/λ + 2π d b: the light's spectral transform F at x = a d with each order
 * m turned by e^{i2πm d b}, which is the series with B and q both turned by e^{i2π d b}. C₀, B, q are
 * taken at DISPERSIVE_SERIES_REFERENCE_NM.
 */
export const DISPERSIVE_SERIES_REFERENCE_NM = 550;

export interface DispersivePhase {
  /** a: Δ(λ) ≈ d (a + b λ) */
  readonly pathPerNm: number;
  /** b, in turns of the phase per nm of thickness */
  readonly turnsPerNm: number;
  /** false where the film is evanescent somewhere in the band (no series) */
  readonly real: boolean;
}

/** The fit of P(λ) = 2 n_b(λ) cos θ_r(λ) to a + bλ for light from n_a at θ_i, over the light's 1 nm knots. */
export function dispersivePhase(stack: Omit<DispersiveFilmStack, 'thicknessNm'>, w: SpectralWeights): DispersivePhase {
  const cos = cosDeg(stack.angleDeg);
  let [s0, s1, s2, t0, t1] = [0, 0, 0, 0, 0];
  let real = true;
  for (let i = 0; i <= LAMBDA_SPAN_NM; i++) {
    const l = LAMBDA_MIN_NM + i;
    const nb = filmIndexAt(stack.nFilm, l);
    const c = refractedCos(nb, stack.nOutside, cos);
    if (c.im !== 0) real = false;
    const p = 2 * nb * c.re;
    // The residual on the phase, (P − a − bλ)/λ, weighted by the light.
    const weight = ((w.x[i] as number) + (w.y[i] as number) + (w.z[i] as number)) / (l * l);
    [s0, s1, s2, t0, t1] = [s0 + weight, s1 + weight * l, s2 + weight * l * l, t0 + weight * p, t1 + weight * p * l];
  }
  const det = s0 * s2 - s1 * s1;
  const a = (t0 * s2 - t1 * s1) / det;
  const b = (s0 * t1 - s1 * t0) / det;
  return { pathPerNm: a, turnsPerNm: b, real };
}

/** The series' terms turned by e^{i2π d b} (see above). */
export function turnedTerms(terms: readonly AirySeriesTerms[], turns: number): AirySeriesTerms[] {
  const angle = 2 * Math.PI * (turns - Math.floor(turns));
  const turn = { re: Math.cos(angle), im: Math.sin(angle) };
  return terms.map((s) => ({ c0: s.c0, b: cMul(s.b, turn), q: cMul(s.q, turn) }));
}

/**
 * The `fourier` method for a dispersive film (twin of the table pass's series fill): the turned
 * series where the film is real across the band and the series converges, else the dispersive bins.
 */
export function dispersiveFourierXyz(
  stack: DispersiveFilmStack,
  polarization: Polarization,
  t: SpectralTransform,
  bins: SpectralBins,
  w: SpectralWeights,
): Xyz {
  const fit = dispersivePhase(stack, w);
  if (fit.real && stack.thicknessNm > 0) {
    const optics = filmOptics(stackAt(stack, DISPERSIVE_SERIES_REFERENCE_NM), polarization);
    const terms = turnedTerms(optics.channels.map(airySeriesTerms), stack.thicknessNm * fit.turnsPerNm);
    const x = stack.thicknessNm * fit.pathPerNm;
    if (seriesConverges(terms, x, t)) return seriesXyz(terms, x, t);
  }
  return dispersiveBinnedXyz(stack, polarization, bins);
}

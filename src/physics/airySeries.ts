import { type Complex, cAbs2, cMul } from './complex.ts';
import { type AiryTerms, type FilmOptics } from './filmReflectance.ts';
import { type SpectralBins, binnedXyz } from './binnedIntegration.ts';
import { type Xyz } from './spectralWeights.ts';
import { type SpectralTransform } from './spectralTransform.ts';

/**
 * The film's colour from the Airy sum as a Fourier series in the phase (docs/physics.md, "The Airy
 * sum as a Fourier series"). For one channel, eq (13) is r = r_ab + Σ_{k≥1} M q^{k−1} e^{ikφ} with
 * M = t_ab t_ba r_bc and q = r_ba r_bc, so R = |r|² (eq 14) is
 *   R(φ) = C₀ + 2 Re Σ_{m≥1} B q^{m−1} e^{imφ},
 *   C₀ = |r_ab|² + |M|² / (1 − |q|²),   B = M conj(r_ab) + |M|² q / (1 − |q|²),
 * and with φ = 2πx/λ (eqs 11, 12: x = Δ = 2 n_b d cos θ_r) eqs (15)–(18) become
 *   X_j = C₀ W_j + 2 Re( B Σ_{m≥1} q^{m−1} F_j(m x) )
 * with F_j the light's spectral transform (spectralTransform.ts). Exact for a real, dispersionless
 * film with a real optical path; an evanescent film (complex Δ) has no such series.
 * Mirrors shaders/physics/airySeries.glsl.
 */
export interface AirySeriesTerms {
  readonly c0: number;
  readonly b: Complex;
  readonly q: Complex;
}

/**
 * C₀, B and q of one channel. Domain: |q| < 1 wherever M ≠ 0 (light enters the film: M ∝
 * t_ab t_ba = 1 − r_ab², which vanishes exactly where |r_ab| = 1).
 */
export function airySeriesTerms(c: AiryTerms): AirySeriesTerms {
  const rab2 = cAbs2(c.rab);
  if (c.multiple.re === 0 && c.multiple.im === 0) return { c0: rab2, b: { re: 0, im: 0 }, q: { re: 0, im: 0 } };
  const g = cAbs2(c.multiple) / (1 - cAbs2(c.roundTrip));
  const direct = cMul(c.multiple, { re: c.rab.re, im: -c.rab.im });
  return { c0: rab2 + g, b: { re: direct.re + g * c.roundTrip.re, im: direct.im + g * c.roundTrip.im }, q: c.roundTrip };
}

/**
 * The series is summed until the terms left, |B| |q|^{m−1} / (1 − |q|) times |F| ≤ W, are below
 * this fraction of the white, or F runs off its table, or AIRY_SERIES_MAX_ORDERS is reached.
 */
export const AIRY_SERIES_TOLERANCE = 1e-5;
/**
 * Terms at most. A soap film needs 3–6 to 80°; high-finesse thin films near grazing incidence
 * (|q| → 1) need thousands, and `airySeriesConverges` sends them to the binned integral instead.
 */
export const AIRY_SERIES_MAX_ORDERS = 128;

/** |B| / (1 − |q|): times |q|^{m−1}, a bound on the terms from order m on, relative to the white. */
const tailScale = (t: AirySeriesTerms): number => Math.hypot(t.b.re, t.b.im) / Math.max(1 - Math.hypot(t.q.re, t.q.im), 1e-7);

/** Whether `maxOrders` terms reach AIRY_SERIES_TOLERANCE or the end of F's table. */
export const airySeriesConverges = (optics: FilmOptics, t: SpectralTransform, maxOrders = AIRY_SERIES_MAX_ORDERS): boolean =>
  seriesConverges(optics.channels.map(airySeriesTerms), optics.opticalPathNm.re, t, maxOrders);

/** The same for the channels' terms at a real path x. */
export function seriesConverges(
  terms: readonly AirySeriesTerms[],
  x: number,
  t: SpectralTransform,
  maxOrders = AIRY_SERIES_MAX_ORDERS,
): boolean {
  if (x * maxOrders >= t.stepNm * (t.count - 1)) return true;
  return terms.every((s) => {
    const scale = tailScale(s);
    const rho = Math.hypot(s.q.re, s.q.im);
    return scale < AIRY_SERIES_TOLERANCE || (rho < 1 && (maxOrders - 1) * Math.log(rho) <= Math.log(AIRY_SERIES_TOLERANCE / scale));
  });
}

/** The carrier e^{i2πσ₀x}, its phase reduced to turns first (as the shader does, for float32). */
export function transformCarrier(t: SpectralTransform, pathNm: number): Complex {
  const turn = t.carrierPerNm * pathNm;
  const angle = 2 * Math.PI * (turn - Math.floor(turn));
  return { re: Math.cos(angle), im: Math.sin(angle) };
}

/**
 * F(x) = H(x) · carrier, H linear between entries, or null past the table (F taken as 0).
 * Returns [Re X, Re Y, Re Z, Im X, Im Y, Im Z].
 */
export function transformAt(t: SpectralTransform, pathNm: number, carrier: Complex): number[] | null {
  const pos = pathNm / t.stepNm;
  const i = Math.floor(pos);
  if (i >= t.count - 1) return null;
  const f = pos - i;
  const h = Array.from({ length: 6 }, (_, k) => (t.values[6 * i + k] as number) * (1 - f) + (t.values[6 * i + 6 + k] as number) * f);
  return [0, 1, 2]
    .map((j) => h[j]! * carrier.re - h[j + 3]! * carrier.im)
    .concat([0, 1, 2].map((j) => h[j]! * carrier.im + h[j + 3]! * carrier.re));
}

/**
 * XYZ of the reflected light by the series, averaged over the optics' channels. Domain: a real
 * optical path (optics.opticalPathNm.im === 0); `maxOrders` below the default truncates the series
 * as peers do (m ≤ 2: three.js/glTF; m ≤ 3: Blender Cycles).
 */
export const airySeriesXyz = (optics: FilmOptics, t: SpectralTransform, maxOrders = AIRY_SERIES_MAX_ORDERS): Xyz =>
  seriesXyz(optics.channels.map(airySeriesTerms), optics.opticalPathNm.re, t, maxOrders);

/** The series of the channels' terms at a real path x, averaged over the channels. */
export function seriesXyz(terms: readonly AirySeriesTerms[], x: number, t: SpectralTransform, maxOrders = AIRY_SERIES_MAX_ORDERS): Xyz {
  const white = [t.values[0] as number, t.values[1] as number, t.values[2] as number];
  const sums = terms.map(() => [0, 0, 0, 0, 0, 0]);
  const powers = terms.map(() => ({ re: 1, im: 0 }));
  const scales = terms.map(tailScale);
  // The carrier of order m is the first one's m-th power.
  const step = transformCarrier(t, x);
  let carrier = step;
  for (let m = 1; m <= maxOrders; m++) {
    const left = Math.max(...terms.map((_, i) => scales[i]! * Math.hypot(powers[i]!.re, powers[i]!.im)));
    if (left < AIRY_SERIES_TOLERANCE) break;
    const f = transformAt(t, m * x, carrier);
    if (!f) break;
    carrier = cMul(carrier, step);
    terms.forEach((s, i) => {
      const p = powers[i]!;
      const sum = sums[i]!;
      for (let j = 0; j < 3; j++) {
        sum[j]! += p.re * f[j]! - p.im * f[j + 3]!;
        sum[j + 3]! += p.re * f[j + 3]! + p.im * f[j]!;
      }
      powers[i] = cMul(p, s.q);
    });
  }
  const xyz = [0, 1, 2].map((j) => {
    let v = 0;
    terms.forEach((s, i) => {
      const sum = sums[i]!;
      v += s.c0 * white[j]! + 2 * (s.b.re * sum[j]! - s.b.im * sum[j + 3]!);
    });
    return v / terms.length;
  });
  return [xyz[0]!, xyz[1]!, xyz[2]!];
}

/**
 * The `fourier` method (shaders/film/filmColor.glsl, mode 2): the series where it has a real optical
 * path and converges within AIRY_SERIES_MAX_ORDERS terms, else the binned integral (evanescent
 * films; high-finesse thin films near grazing incidence). A line source's transform never decays,
 * so the series has no end there: its lines are summed directly (the bins' lines).
 */
export const fourierXyz = (optics: FilmOptics, t: SpectralTransform, bins: SpectralBins): Xyz =>
  !bins.lines && optics.opticalPathNm.im === 0 && airySeriesConverges(optics, t) ? airySeriesXyz(optics, t) : binnedXyz(optics, bins);

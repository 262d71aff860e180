import FFT from 'fft.js';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from './spectralConventions.ts';
import { type SpectralWeights } from './spectralWeights.ts';
import { interpolateTable } from './tableInterpolation.ts';

/**
 * The light's spectral transform (docs/physics.md, "The Airy sum as a Fourier series"):
 *   F_j(x) = ∫ w_j(λ) e^{i2πx/λ} dλ over 380–830 nm,  w_j = I_in · {x̄, ȳ, z̄} / k  (eqs 15–18),
 * one complex function of the optical path x per tristimulus channel. It depends on the light
 * and the normalisation only — not on the film, its indices or the angle — and F_j(0) is the
 * white's tristimulus value W_j.
 *
 * Tabulated every SPECTRAL_TRANSFORM_STEP_NM (≈ 10 nm) of x from 0 to SPECTRAL_TRANSFORM_MAX_PATH_NM,
 * demodulated: H_j(x) = F_j(x) e^{−i2πσ₀x} with σ₀ the middle of the band in wavenumber, so H
 * turns at most π·(1/380 − 1/830) rad per nm of x and linear interpolation between entries is
 * within ~3e-4 of |F|. Past the table F is taken as 0: the light's coherence length is a few µm.
 */
export interface SpectralTransform {
  /** x of entry i is i · stepNm */
  readonly stepNm: number;
  readonly count: number;
  /** σ₀ in 1/nm: F(x) = H(x) e^{i2πσ₀x} */
  readonly carrierPerNm: number;
  /** H at entry i: Re X, Re Y, Re Z, Im X, Im Y, Im Z at 6i … 6i + 5 */
  readonly values: Float64Array;
}

const SIGMA_MIN = 1 / LAMBDA_MAX_NM;
const SIGMA_MAX = 1 / LAMBDA_MIN_NM;
const FFT_SIZE = 1 << 18;
/** Wavenumber samples across the band: Δσ ≈ 3.8e-7 / nm (0.12 nm of λ at 550 nm). */
const BAND_SAMPLES = 3740;
const D_SIGMA = (SIGMA_MAX - SIGMA_MIN) / BAND_SAMPLES;
/** x step of the DFT: Δx · Δσ = 1 / FFT_SIZE. */
export const SPECTRAL_TRANSFORM_STEP_NM = 1 / (FFT_SIZE * D_SIGMA);
export const SPECTRAL_TRANSFORM_MAX_PATH_NM = 250_000;
export const SPECTRAL_TRANSFORM_COUNT = Math.ceil(SPECTRAL_TRANSFORM_MAX_PATH_NM / SPECTRAL_TRANSFORM_STEP_NM) + 1;
export const SPECTRAL_TRANSFORM_CARRIER_PER_NM = (SIGMA_MIN + SIGMA_MAX) / 2;

let fft: FFT | null = null;

/**
 * F_j for a light's weights. With σ = 1/λ, dλ = dσ/σ², F_j(x) = ∫ v_j(σ) e^{i2πxσ} dσ,
 * v_j(σ) = w_j(1/σ)/σ²; the trapezoid rule on BAND_SAMPLES equal steps of σ makes every x_k = kΔx
 * one term of a discrete Fourier transform, computed by FFT (three real transforms of FFT_SIZE
 * points: longer than a frame on a busy CPU, so the app runs it in a worker,
 * docs/gpu.md#nothing-waits-on-the-main-thread).
 */
export function spectralTransform(w: SpectralWeights): SpectralTransform {
  fft ??= new FFT(FFT_SIZE);
  const count = SPECTRAL_TRANSFORM_COUNT;
  const values = new Float64Array(6 * count);
  const input = new Float64Array(FFT_SIZE);
  const out = fft.createComplexArray() as number[];
  [w.x, w.y, w.z].forEach((t, channel) => {
    for (let j = 0; j <= BAND_SAMPLES; j++) {
      const sigma = SIGMA_MIN + j * D_SIGMA;
      const trapezoid = j === 0 || j === BAND_SAMPLES ? 0.5 : 1;
      // w linear between its 1 nm knots, as the reference integrates it.
      input[j] = (trapezoid * D_SIGMA * interpolateTable(t, LAMBDA_MIN_NM, 1, 1 / sigma)) / (sigma * sigma);
    }
    fft!.realTransform(out, input);
    for (let k = 0; k < count; k++) {
      // FFT gives Σ a_j e^{−i2πjk/N}; the conjugate is Σ a_j e^{+i2πjk/N} (a_j real). σ_j = σ_min + jΔσ,
      // so H(x_k) = e^{i2πx_k(σ_min − σ₀)} · conj(out_k).
      const re = out[2 * k] as number;
      const im = -(out[2 * k + 1] as number);
      const shift = 2 * Math.PI * ((k * (SIGMA_MIN - SPECTRAL_TRANSFORM_CARRIER_PER_NM)) / (FFT_SIZE * D_SIGMA));
      const c = Math.cos(shift);
      const s = Math.sin(shift);
      values[6 * k + channel] = re * c - im * s;
      values[6 * k + 3 + channel] = re * s + im * c;
    }
  });
  return { stepNm: SPECTRAL_TRANSFORM_STEP_NM, count, carrierPerNm: SPECTRAL_TRANSFORM_CARRIER_PER_NM, values };
}

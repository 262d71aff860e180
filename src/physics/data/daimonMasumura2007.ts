/**
 * Water at 20 °C: the four-term Sellmeier formula of M. Daimon and A. Masumura, "Measurement of
 * the refractive index of distilled water from the near-infrared region to the ultraviolet
 * region", Appl. Opt. 46, 3811–3820 (2007), their fit at 20.0 °C:
 *   n² − 1 = Σ_i K_i λ² / (λ² − L_i),   λ in µm, L_i in µm², absolute (vacuum) index, valid 182–1129 nm.
 */
export const DAIMON_MASUMURA_2007_WATER_20C = {
  k: [5.684027565e-1, 1.726177391e-1, 2.086189578e-2, 1.130748688e-1],
  lUm2: [5.101829712e-3, 1.821153936e-2, 2.620722293e-2, 1.069792721e1],
} as const;

/**
 * Fused silica (SiO2) at 20 °C: the three-term Sellmeier formula of I. H. Malitson,
 * "Interspecimen comparison of the refractive index of fused silica", J. Opt. Soc. Am. 55,
 * 1205–1208 (1965), DOI 10.1364/JOSA.55.001205:
 *   n² − 1 = Σ_i B_i λ² / (λ² − C_i²),   λ in µm, valid 0.21–3.71 µm.
 *
 * Coefficients (numbers only) as the refractiveindex.info database (M. N. Polyanskiy, Sci. Data 11,
 * 94 (2024), DOI 10.1038/s41597-023-02898-2; CC0 1.0) lists them, database/data/main/SiO2/nk/Malitson.yml.
 */
export const MALITSON_1965_SILICA = {
  b: [0.6961663, 0.4079426, 0.8974794],
  cUm: [0.0684043, 0.1162414, 9.896161],
} as const;

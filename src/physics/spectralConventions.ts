/**
 * The conventions of eqs (16)–(18) that checking a setting needs without the CIE tables
 * (spectralWeights.ts computes the weights from them): the integration range and the normalisations.
 */

/** The integration range of eqs (16)–(18). */
export const LAMBDA_MIN_NM = 380;
export const LAMBDA_MAX_NM = 830;
export const LAMBDA_SPAN_NM = LAMBDA_MAX_NM - LAMBDA_MIN_NM;

/**
 * Normalisation of eqs (16)–(18):
 * - `white`: k = ∫ I_in ȳ dλ, so a perfect white reflector has Y = 1 (default);
 * - `paper`: the paper's k = ∫ ȳ dλ, with I_in scaled to 1 at 560 nm.
 */
export const NORMALIZATIONS = ['white', 'paper'] as const;
export type Normalization = (typeof NORMALIZATIONS)[number];

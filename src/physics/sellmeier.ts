/**
 * A Sellmeier formula, n² − 1 = Σ_i B_i λ² / (λ² − C_i), λ in µm and C_i in µm²: the form of the
 * published fits of fused silica (Malitson 1965, data/malitson1965.ts) and water (Daimon and
 * Masumura 2007, data/daimonMasumura2007.ts).
 */
export interface SellmeierTerms {
  readonly b: readonly number[];
  /** C_i in µm² (a source that gives the resonance wavelength λ_i in µm gives C_i = λ_i²) */
  readonly cUm2: readonly number[];
}

/** n(λ) of a Sellmeier formula, λ in nm: real, the medium transparent where the formula holds. */
export const sellmeier =
  ({ b, cUm2 }: SellmeierTerms) =>
  (lambdaNm: number): number => {
    const x = (lambdaNm / 1000) ** 2;
    let n2 = 1;
    b.forEach((bi, i) => (n2 += (bi * x) / (x - cUm2[i]!)));
    return Math.sqrt(n2);
  };

/**
 * Aluminium as the Lorentz–Drude model of A. D. Rakić, A. B. Djurišić, J. M. Elazar and
 * M. L. Majewski, "Optical properties of metallic films for vertical-cavity optoelectronic
 * devices", Appl. Opt. 37, 5271–5283 (1998), DOI 10.1364/AO.37.005271: a fit to measurements from
 * several sources,
 *   ε(ω) = 1 − f0 ω_p² / (ω (ω + iΓ0)) + Σ_j f_j ω_p² / (ω_j² − ω² − iωΓ_j),   ħω in eV,
 * in the e^{−iωt} convention (Im ε ≥ 0: absorbing), ñ = √ε.
 *
 * Parameters (numbers only) as the refractiveindex.info database (M. N. Polyanskiy, Sci. Data 11,
 * 94 (2024), DOI 10.1038/s41597-023-02898-2; CC0 1.0) lists them for its tabulation of this model,
 * database/data/main/Al/nk/Rakic-LD.yml (script "Rakic 1998 - Al (LD model).py" in
 * polyanskiy/refractiveindex.info-scripts).
 */
export const RAKIC_1998_ALUMINIUM = {
  plasmaEv: 14.98,
  drude: { f: 0.523, gammaEv: 0.047 },
  oscillators: [
    { f: 0.227, gammaEv: 0.333, omegaEv: 0.162 },
    { f: 0.05, gammaEv: 0.312, omegaEv: 1.544 },
    { f: 0.166, gammaEv: 1.351, omegaEv: 1.808 },
    { f: 0.03, gammaEv: 3.382, omegaEv: 3.473 },
  ],
} as const;

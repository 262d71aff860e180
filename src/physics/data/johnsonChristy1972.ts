/**
 * Optical constants ñ = n + ik of gold, silver and copper at room temperature: P. B. Johnson and
 * R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6, 4370–4379 (1972),
 * DOI 10.1103/PhysRevB.6.4370. Measured at fixed photon energies 0.64–6.6 eV (187.9–1937 nm);
 * these are the rows covering 380–830 nm and one beyond each end (1.39–3.37 eV, 367.9–892.0 nm).
 *
 * Transcribed (numbers only) from the refractiveindex.info database (M. N. Polyanskiy, "Refractiveindex.info database of optical
 * constants", Sci. Data 11, 94 (2024), DOI 10.1038/s41597-023-02898-2), repository
 * polyanskiy/refractiveindex.info-database, dedicated to the public domain under CC0 1.0:
 * database/data/main/{Au,Ag,Cu}/nk/Johnson.yml.
 */
import type { NkTable } from '../tabulatedIndex.ts';

/** Rows [λ in µm, n, k], λ ascending, as the database lists them. */
export const JOHNSON_CHRISTY_1972 = {
  Au: [
    [0.3679, 1.48, 1.895],
    [0.3815, 1.46, 1.933],
    [0.3974, 1.47, 1.952],
    [0.4133, 1.46, 1.958],
    [0.4305, 1.45, 1.948],
    [0.4509, 1.38, 1.914],
    [0.4714, 1.31, 1.849],
    [0.4959, 1.04, 1.833],
    [0.5209, 0.62, 2.081],
    [0.5486, 0.43, 2.455],
    [0.5821, 0.29, 2.863],
    [0.6168, 0.21, 3.272],
    [0.6595, 0.14, 3.697],
    [0.7045, 0.13, 4.103],
    [0.756, 0.14, 4.542],
    [0.8211, 0.16, 5.083],
    [0.892, 0.17, 5.663],
  ],
  Ag: [
    [0.3679, 0.07, 1.657],
    [0.3815, 0.05, 1.864],
    [0.3974, 0.05, 2.07],
    [0.4133, 0.05, 2.275],
    [0.4305, 0.04, 2.462],
    [0.4509, 0.04, 2.657],
    [0.4714, 0.05, 2.869],
    [0.4959, 0.05, 3.093],
    [0.5209, 0.05, 3.324],
    [0.5486, 0.06, 3.586],
    [0.5821, 0.05, 3.858],
    [0.6168, 0.06, 4.152],
    [0.6595, 0.05, 4.483],
    [0.7045, 0.04, 4.838],
    [0.756, 0.03, 5.242],
    [0.8211, 0.04, 5.727],
    [0.892, 0.04, 6.312],
  ],
  Cu: [
    [0.3679, 1.36, 1.975],
    [0.3815, 1.33, 2.045],
    [0.3974, 1.32, 2.116],
    [0.4133, 1.28, 2.207],
    [0.4305, 1.25, 2.305],
    [0.4509, 1.24, 2.397],
    [0.4714, 1.25, 2.483],
    [0.4959, 1.22, 2.564],
    [0.5209, 1.18, 2.608],
    [0.5486, 1.02, 2.577],
    [0.5821, 0.7, 2.704],
    [0.6168, 0.3, 3.205],
    [0.6595, 0.22, 3.747],
    [0.7045, 0.21, 4.205],
    [0.756, 0.24, 4.665],
    [0.8211, 0.26, 5.18],
    [0.892, 0.3, 5.768],
  ],
} as const satisfies Record<string, NkTable>;

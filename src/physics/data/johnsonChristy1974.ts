/**
 * Optical constants ñ = n + ik of titanium, iron, chromium and nickel at room temperature:
 * P. B. Johnson and R. W. Christy, "Optical constants of transition metals: Ti, V, Cr, Mn, Fe, Co,
 * Ni, and Pd", Phys. Rev. B 9, 5056–5070 (1974), DOI 10.1103/PhysRevB.9.5056. Measured at the same
 * photon energies as the 1972 noble-metal table, the wavelengths listed to 1 nm; these are the rows
 * covering 380–830 nm and one beyond each end (368–892 nm).
 *
 * Transcribed (numbers only) from the refractiveindex.info database (M. N. Polyanskiy, "Refractiveindex.info database of optical
 * constants", Sci. Data 11, 94 (2024), DOI 10.1038/s41597-023-02898-2), repository
 * polyanskiy/refractiveindex.info-database, dedicated to the public domain under CC0 1.0:
 * database/data/main/{Ti,Fe,Cr,Ni}/nk/Johnson.yml.
 */
import type { NkTable } from '../tabulatedIndex.ts';

/** Rows [λ in µm, n, k], λ ascending, as the database lists them. */
export const JOHNSON_CHRISTY_1974 = {
  Ti: [
    [0.368, 1.9, 2.9],
    [0.381, 1.99, 2.93],
    [0.397, 2.08, 2.95],
    [0.413, 2.14, 2.98],
    [0.431, 2.21, 3.01],
    [0.451, 2.27, 3.04],
    [0.471, 2.32, 3.1],
    [0.496, 2.36, 3.19],
    [0.521, 2.44, 3.3],
    [0.549, 2.54, 3.43],
    [0.582, 2.6, 3.58],
    [0.617, 2.67, 3.72],
    [0.659, 2.76, 3.84],
    [0.704, 2.86, 3.96],
    [0.756, 3.0, 4.01],
    [0.821, 3.21, 4.01],
    [0.892, 3.29, 3.96],
  ],
  Fe: [
    [0.368, 2.02, 2.43],
    [0.381, 2.12, 2.5],
    [0.397, 2.24, 2.58],
    [0.413, 2.35, 2.65],
    [0.431, 2.48, 2.71],
    [0.451, 2.59, 2.77],
    [0.471, 2.67, 2.82],
    [0.496, 2.74, 2.88],
    [0.521, 2.86, 2.91],
    [0.549, 2.95, 2.93],
    [0.582, 2.94, 2.99],
    [0.617, 2.88, 3.05],
    [0.659, 2.92, 3.1],
    [0.704, 2.86, 3.19],
    [0.756, 2.87, 3.28],
    [0.821, 2.94, 3.39],
    [0.892, 2.96, 3.56],
  ],
  Cr: [
    [0.368, 1.87, 2.69],
    [0.381, 1.92, 2.74],
    [0.397, 2.0, 2.83],
    [0.413, 2.08, 2.93],
    [0.431, 2.19, 3.04],
    [0.451, 2.33, 3.14],
    [0.471, 2.51, 3.24],
    [0.496, 2.75, 3.3],
    [0.521, 2.94, 3.33],
    [0.549, 3.18, 3.33],
    [0.582, 3.22, 3.3],
    [0.617, 3.17, 3.3],
    [0.659, 3.09, 3.34],
    [0.704, 3.05, 3.39],
    [0.756, 3.08, 3.42],
    [0.821, 3.2, 3.48],
    [0.892, 3.3, 3.52],
  ],
  Ni: [
    [0.368, 1.7, 2.4],
    [0.381, 1.72, 2.48],
    [0.397, 1.72, 2.57],
    [0.413, 1.7, 2.69],
    [0.431, 1.71, 2.82],
    [0.451, 1.73, 2.95],
    [0.471, 1.78, 3.09],
    [0.496, 1.82, 3.25],
    [0.521, 1.85, 3.42],
    [0.549, 1.92, 3.61],
    [0.582, 1.96, 3.8],
    [0.617, 1.99, 4.02],
    [0.659, 1.99, 4.26],
    [0.704, 2.06, 4.5],
    [0.756, 2.13, 4.73],
    [0.821, 2.26, 4.97],
    [0.892, 2.4, 5.23],
  ],
} as const satisfies Record<string, NkTable>;

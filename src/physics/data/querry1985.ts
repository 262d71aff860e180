/**
 * Optical constants ñ = n + ik of magnetite (Fe3O4): M. R. Querry, "Optical constants", Contractor
 * Report CRDC-CR-85034 (US Army Chemical Research and Development Center, 1985), DTIC ADA158623
 * (a report without a DOI). Tabulated every 10 nm in the visible; these are the rows covering
 * 380–830 nm and one beyond each end (370–840 nm).
 *
 * Transcribed (numbers only) from the refractiveindex.info database (M. N. Polyanskiy, "Refractiveindex.info database of optical
 * constants", Sci. Data 11, 94 (2024), DOI 10.1038/s41597-023-02898-2), repository
 * polyanskiy/refractiveindex.info-database, dedicated to the public domain under CC0 1.0:
 * database/data/main/Fe3O4/nk/Querry.yml.
 */
import type { NkTable } from '../tabulatedIndex.ts';

/** Rows [λ in µm, n, k], λ ascending, as the database lists them. */
export const QUERRY_1985 = {
  Fe3O4: [
    [0.37, 2.447, 0.108],
    [0.38, 2.459, 0.096],
    [0.39, 2.464, 0.08],
    [0.4, 2.462, 0.062],
    [0.41, 2.453, 0.047],
    [0.42, 2.44, 0.034],
    [0.43, 2.423, 0.026],
    [0.44, 2.404, 0.026],
    [0.45, 2.386, 0.032],
    [0.46, 2.374, 0.042],
    [0.47, 2.367, 0.054],
    [0.48, 2.365, 0.063],
    [0.49, 2.364, 0.067],
    [0.5, 2.359, 0.071],
    [0.51, 2.354, 0.077],
    [0.52, 2.349, 0.083],
    [0.53, 2.346, 0.091],
    [0.54, 2.344, 0.099],
    [0.55, 2.343, 0.105],
    [0.56, 2.342, 0.112],
    [0.57, 2.342, 0.118],
    [0.58, 2.342, 0.125],
    [0.59, 2.344, 0.131],
    [0.6, 2.346, 0.136],
    [0.61, 2.35, 0.141],
    [0.62, 2.353, 0.144],
    [0.63, 2.358, 0.148],
    [0.64, 2.366, 0.145],
    [0.65, 2.366, 0.138],
    [0.66, 2.363, 0.137],
    [0.67, 2.364, 0.135],
    [0.68, 2.362, 0.131],
    [0.69, 2.359, 0.127],
    [0.7, 2.355, 0.124],
    [0.71, 2.349, 0.122],
    [0.72, 2.343, 0.12],
    [0.73, 2.336, 0.119],
    [0.74, 2.329, 0.118],
    [0.75, 2.32, 0.118],
    [0.76, 2.312, 0.119],
    [0.77, 2.303, 0.12],
    [0.78, 2.294, 0.123],
    [0.79, 2.284, 0.128],
    [0.8, 2.279, 0.134],
    [0.81, 2.272, 0.134],
    [0.82, 2.262, 0.138],
    [0.83, 2.253, 0.143],
    [0.84, 2.245, 0.149],
  ],
} as const satisfies Record<string, NkTable>;

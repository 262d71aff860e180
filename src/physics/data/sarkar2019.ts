/**
 * Refractive index of a titanium dioxide thin film (200 nm on glass): S. Sarkar, V. Gupta, M. Kumar,
 * J. Schubert, P. T. Probst, J. Joseph and T. A. F. König, "Hybridized guided-mode resonances via
 * colloidal plasmonic self-assembled grating", ACS Appl. Mater. Interfaces 11, 13752–13760 (2019),
 * DOI 10.1021/acsami.8b20535. The source tabulates n and k every 1 nm; these are its rows every
 * 10 nm from 370 to 840 nm (k is 0 to its six decimals above 364 nm, so the film is transparent
 * over the colour band).
 *
 * Transcribed (numbers only) from the refractiveindex.info database (M. N. Polyanskiy, "Refractiveindex.info database of optical
 * constants", Sci. Data 11, 94 (2024), DOI 10.1038/s41597-023-02898-2), repository
 * polyanskiy/refractiveindex.info-database, dedicated to the public domain under CC0 1.0:
 * database/data/main/TiO2/nk/Sarkar.yml.
 */
import type { NkTable } from '../tabulatedIndex.ts';

/** Rows [λ in µm, n, k], λ ascending, as the database lists them. */
export const SARKAR_2019 = {
  TiO2: [
    [0.37, 2.442075, 0.0],
    [0.38, 2.3993, 0.0],
    [0.39, 2.365628, 0.0],
    [0.4, 2.337928, 0.0],
    [0.41, 2.314541, 0.0],
    [0.42, 2.294437, 0.0],
    [0.43, 2.276919, 0.0],
    [0.44, 2.261491, 0.0],
    [0.45, 2.247783, 0.0],
    [0.46, 2.235515, 0.0],
    [0.47, 2.224466, 0.0],
    [0.48, 2.214461, 0.0],
    [0.49, 2.205359, 0.0],
    [0.5, 2.197043, 0.0],
    [0.51, 2.189417, 0.0],
    [0.52, 2.182399, 0.0],
    [0.53, 2.17592, 0.0],
    [0.54, 2.169924, 0.0],
    [0.55, 2.164358, 0.0],
    [0.56, 2.15918, 0.0],
    [0.57, 2.154353, 0.0],
    [0.58, 2.149843, 0.0],
    [0.59, 2.145621, 0.0],
    [0.6, 2.141661, 0.0],
    [0.61, 2.137942, 0.0],
    [0.62, 2.134443, 0.0],
    [0.63, 2.131146, 0.0],
    [0.64, 2.128036, 0.0],
    [0.65, 2.125097, 0.0],
    [0.66, 2.122316, 0.0],
    [0.67, 2.119682, 0.0],
    [0.68, 2.117185, 0.0],
    [0.69, 2.114814, 0.0],
    [0.7, 2.112561, 0.0],
    [0.71, 2.110419, 0.0],
    [0.72, 2.108378, 0.0],
    [0.73, 2.106434, 0.0],
    [0.74, 2.104579, 0.0],
    [0.75, 2.102809, 0.0],
    [0.76, 2.101118, 0.0],
    [0.77, 2.0995, 0.0],
    [0.78, 2.097953, 0.0],
    [0.79, 2.096471, 0.0],
    [0.8, 2.095051, 0.0],
    [0.81, 2.09369, 0.0],
    [0.82, 2.092383, 0.0],
    [0.83, 2.091129, 0.0],
    [0.84, 2.089925, 0.0],
  ],
} as const satisfies Record<string, NkTable>;

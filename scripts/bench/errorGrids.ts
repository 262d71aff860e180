/**
 * The benchmark's two error grids (a soap film n_film 1.33 in air, D65, unpolarised, white
 * normalisation) and their ΔE00 against the float64 reference (src/physics).
 */
import { deltaE00 } from '../../src/physics/colorDifference.ts';
import { cosDeg } from '../../src/physics/snell.ts';
import { filmXyz, whiteXyz } from '../../src/physics/spectralIntegration.ts';
import { type Xyz } from '../../src/physics/spectralWeights.ts';
import { type DeltaStats, deltaStats } from '../harness/deltaStats.ts';
import type { ParityGroup } from '../harness/parityCase.ts';

const SOAP = { nOutside: 1, nFilm: 1.33, nInside: 1, illuminant: 'D65', polarization: 'unpolarized', normalization: 'white' } as const;
const range = (n: number, f: (i: number) => number) => Array.from({ length: n }, (_, i) => f(i));

function grid(thicknessesNm: readonly number[], anglesDeg: readonly number[]): ParityGroup {
  return { ...SOAP, inputs: thicknessesNm.flatMap((t) => anglesDeg.map((a) => [t, cosDeg(a)] as const)) };
}

/** 0–2000 nm every 10 nm × 0–85° every 5°: 3618 films. */
export const FIXED_GRID = grid(
  range(201, (i) => 10 * i),
  range(18, (i) => 5 * i),
);

/**
 * 0–20 µm, 161 thicknesses spaced quadratically (so thin films, whose colour changes fastest, get
 * steps from 0.8 nm) × 0–85° every 5° and 86°–89.9° in 7 steps: 4025 films.
 */
export const STRESS_GRID = grid(
  range(161, (i) => 20000 * (i / 160) ** 2),
  [...range(18, (i) => 5 * i), 86, 87, 88, 88.5, 89, 89.5, 89.9],
);

/** The reference's XYZ of every case of a grid (computed once per run). */
export function referenceXyz(g: ParityGroup): Xyz[] {
  return g.inputs.map(([thicknessNm, cosIncidence]) =>
    filmXyz({ ...g, thicknessNm, angleDeg: (Math.acos(Math.min(1, cosIncidence)) * 180) / Math.PI }, g),
  );
}

export interface GridError extends DeltaStats {
  /** the film with the largest ΔE00 */
  readonly worst: { readonly thicknessNm: number; readonly angleDeg: number };
}

export function gridError(g: ParityGroup, reference: readonly Xyz[], shader: readonly number[][]): GridError {
  const white = whiteXyz(g.illuminant, g.normalization);
  const deltas = reference.map((r, i) => deltaE00(shader[i] as unknown as Xyz, r, white));
  const [thicknessNm, cosIncidence] = g.inputs[deltas.indexOf(Math.max(...deltas))]!;
  return { ...deltaStats(deltas), worst: { thicknessNm, angleDeg: (Math.acos(cosIncidence) * 180) / Math.PI } };
}

/**
 * gridError over the grid's films thicker than 0 nm: the whole material's measure, as three turns
 * its film off at 0 nm and draws its own base there (Schlick's Fresnel).
 */
export function filmsGridError(g: ParityGroup, reference: readonly Xyz[], shader: readonly number[][]): GridError {
  const films = g.inputs.flatMap(([t], k) => (t > 0 ? [k] : []));
  return gridError(
    { ...g, inputs: films.map((k) => g.inputs[k]!) },
    films.map((k) => reference[k]!),
    films.map((k) => shader[k]!),
  );
}

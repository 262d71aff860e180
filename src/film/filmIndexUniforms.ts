import { type FilmIndex, filmIndexAt, isDispersive } from '../physics/filmIndex.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM } from '../physics/spectralWeights.ts';

/** The spacing of shaders/physics/filmIndex.glsl's knots: linear between them, n_b is within 3e-6 of water's (docs/physics.md#a-dispersive-film). */
const STEP_NM = 5;
const KNOTS = LAMBDA_SPAN_NM / STEP_NM + 1;

/** The sodium D line: the wavelength of the one index that consumers without dispersion take (uNFilm; three.js's iridescence). */
export const SODIUM_D_NM = 589.29;

/** The defines of a film-colour shader for this index: TFC_DISPERSIVE and its knots, or none for a constant index. */
export const filmIndexDefines = (index: FilmIndex): Record<string, number> =>
  isDispersive(index)
    ? { TFC_DISPERSIVE: 1, TFC_FILM_INDEX_KNOTS: KNOTS, TFC_FILM_INDEX_FIRST_NM: LAMBDA_MIN_NM, TFC_FILM_INDEX_STEP_NM: STEP_NM }
    : {};

/** The film-index uniforms of shaders/film/filmColor.glsl, filmTable.glsl and filmIndex.glsl. */
export const filmIndexUniforms = () => ({
  uNFilm: { value: 1.33 },
  uFilmIndexKnots: { value: new Float32Array(4 * Math.ceil(KNOTS / 4)) },
});

/** Sets them: uNFilm to n_b (at the D line if it varies), uFilmIndexKnots to n_b every STEP_NM (filmIndexAt in float64). */
export function updateFilmIndexUniforms(u: Record<string, { value: unknown }>, index: FilmIndex): void {
  u.uNFilm!.value = filmIndexAt(index, SODIUM_D_NM);
  const knots = u.uFilmIndexKnots!.value as Float32Array;
  for (let i = 0; i < KNOTS; i++) knots[i] = filmIndexAt(index, LAMBDA_MIN_NM + i * STEP_NM);
}

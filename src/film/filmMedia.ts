import { packTexelRecord, texelRecord, texelRecordDefines } from '../gpu/texelRecord.ts';
import { asComplex } from '../physics/complex.ts';
import { type Medium, absorbsInBand, isDispersiveMedium, mediumIndexAt } from '../physics/medium.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM } from '../physics/spectralWeights.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';

/** The three media of the film: outside (a), the film (b), inside (c). */
export type FilmMedia = Pick<FilmSettings, 'nOutside' | 'nFilm' | 'nInside'>;

/** The spacing of shaders/physics/medium.glsl's knots: linear between them, n_b is within 3e-6 of water's (docs/physics.md#a-dispersive-film). */
const STEP_NM = 5;
const KNOTS = LAMBDA_SPAN_NM / STEP_NM + 1;

/**
 * A knot of shaders/physics/medium.glsl: the film's and the inside's ñ as (n, k), read by these
 * names in filmMedia.glsl (`tfcKnotMedia`). One texel: medium.glsl holds a vec4 per knot.
 */
export const MEDIA_KNOT = texelRecord('TFC_MEDIA_KNOT', { FILM: 2, INSIDE: 2 });

/** The sodium D line: the wavelength of the one index that consumers without dispersion take (uNFilm; three.js's iridescence). */
export const SODIUM_D_NM = 589.29;

/**
 * The defines of the media's knots: TFC_DISPERSIVE, for a film whose film or inside depends on λ
 * (the shaders then take both per spectral bin). A stack of films takes every medium per bin from
 * its own texture (filmStack.ts): none of this. filmFillGpu.ts says which fill takes them.
 */
export const MEDIA_KNOT_DEFINES: Readonly<Record<string, number>> = {
  TFC_DISPERSIVE: 1,
  TFC_MEDIA_KNOTS: KNOTS,
  TFC_MEDIA_FIRST_NM: LAMBDA_MIN_NM,
  TFC_MEDIA_STEP_NM: STEP_NM,
  ...texelRecordDefines(MEDIA_KNOT),
};

/** TFC_OPAQUE_INSIDE where the inside absorbs (no light from inside), which every film-colour shader reads. */
export const opaqueInsideDefines = (s: Pick<FilmMedia, 'nInside'>): Record<string, number> =>
  absorbsInBand(s.nInside) ? { TFC_OPAQUE_INSIDE: 1 } : {};

/**
 * The media's uniforms, declared once in GLSL by shaders/film/filmMedia.glsl (and the knots by
 * medium.glsl): every film-colour shader (the bubble, the table pass, the material, the parity
 * probe) takes them from here. ñ as [n, k].
 */
export const filmMediaUniforms = () => ({
  uNOutside: { value: 1 },
  uNFilm: { value: [1.33, 0] },
  uNInside: { value: [1, 0] },
  uMediaKnots: { value: new Float32Array(MEDIA_KNOT.floats * KNOTS) },
});

const nk = (m: Medium, lambdaNm: number): [number, number] => {
  const z = asComplex(mediumIndexAt(m, lambdaNm));
  return [z.re, z.im];
};

/** The film's largest real index over the band (at the knots; at every λ for a constant one): its fringes are closest there. */
export function filmIndexMax(nFilm: Medium): number {
  if (!isDispersiveMedium(nFilm)) return nk(nFilm, SODIUM_D_NM)[0];
  let max = 0;
  for (let i = 0; i < KNOTS; i++) max = Math.max(max, nk(nFilm, LAMBDA_MIN_NM + i * STEP_NM)[0]);
  return max;
}

/** Sets the three indices to `s`: ñ_b and ñ_c at the D line where they vary. */
export function setFilmMediaIndices(u: Record<string, { value: unknown }>, s: FilmMedia): void {
  u.uNOutside!.value = s.nOutside;
  u.uNFilm!.value = nk(s.nFilm, SODIUM_D_NM);
  u.uNInside!.value = nk(s.nInside, SODIUM_D_NM);
}

/** Sets the knots to the film's and the inside's ñ every STEP_NM (mediumIndexAt in float64). */
export function setMediaKnots(u: Record<string, { value: unknown }>, s: Pick<FilmMedia, 'nFilm' | 'nInside'>): void {
  const knots = u.uMediaKnots!.value as Float32Array;
  for (let i = 0; i < KNOTS; i++) {
    const lambdaNm = LAMBDA_MIN_NM + i * STEP_NM;
    packTexelRecord(MEDIA_KNOT, knots, i, { FILM: nk(s.nFilm, lambdaNm), INSIDE: nk(s.nInside, lambdaNm) });
  }
}

import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { type FieldInput, type FieldUniforms, type TimelessInput, numberSetting } from './thicknessField.ts';

/** GLSL's smoothstep. */
const smoothstep = (e0: number, e1: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - e0) / (e1 - e0)));
  return t * t * (3 - 2 * t);
};
const clamp = (x: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, x));

/** The drained film's own setting, its top-to-bottom difference in nm: one declaration for every field of a drained film. */
export const DRAINED_FILM_SETTINGS = {
  thicknessRangeNm: numberSetting('thicknessRange', FILM_STACK_DOMAIN.thicknessNm, 800, 1, 'film'),
};
type DrainedFilmSettings = FieldInput<typeof DRAINED_FILM_SETTINGS>;

/** The drained film's uniforms (shaders/fields/drainedFilm.glsl declares them). */
export const drainedFilmUniforms = (): FieldUniforms => ({ uThicknessNm: { value: 500 }, uThicknessRangeNm: { value: 0 } });

export function updateDrainedFilmUniforms(u: FieldUniforms, s: DrainedFilmSettings): void {
  u.uThicknessNm!.value = s.thicknessNm;
  u.uThicknessRangeNm!.value = s.thicknessRangeNm;
}

/**
 * A film drained by gravity (twin of tfcDrainedThicknessNm): thin at the top, thick at the
 * bottom, linear in the height `h` (clamped to ±1) about the mean, down to a ~10 nm black film in
 * a cap around the top (`y`: the point's own height).
 */
export function drainedThicknessNm(h: number, y: number, s: DrainedFilmSettings): number {
  const d = s.thicknessNm - 0.5 * s.thicknessRangeNm * clamp(h, -1, 1);
  const capped = Math.max(d, 10) + (10 - Math.max(d, 10)) * smoothstep(0.82, 0.95, y);
  return clamp(capped, FILM_STACK_DOMAIN.thicknessNm.min, FILM_STACK_DOMAIN.thicknessNm.max);
}

/** The thickest the drained film gets: the mean plus half the range, at the bottom. */
export const drainedFilmMaxNm = (s: TimelessInput<typeof DRAINED_FILM_SETTINGS>): number =>
  Math.min(FILM_STACK_DOMAIN.thicknessNm.max, Math.max(s.thicknessNm + 0.5 * s.thicknessRangeNm, 1));

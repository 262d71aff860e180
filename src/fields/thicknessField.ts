import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { FIELDS, type FilmSettings } from '../settings/filmSettings.ts';
import { enumDefines } from '../gpu/enumDefines.ts';

/** The defines of shaders/fields/thicknessField.glsl for the field shown. */
export const thicknessFieldDefines = (s: Pick<FilmSettings, 'field'>): Record<string, number> =>
  enumDefines('TFC_THICKNESS_FIELD', FIELDS, s.field);

/** A point on the unit sphere, y up. */
export type Vec3 = readonly [number, number, number];

/** GLSL's smoothstep. */
const smoothstep = (e0: number, e1: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - e0) / (e1 - e0)));
  return t * t * (3 - 2 * t);
};
const clamp = (x: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, x));

/** Film thickness in nm at point p of the bubble: the twin of shaders/fields/thicknessField.glsl. */
export function thicknessAt(
  [x, y, z]: Vec3,
  s: Pick<FilmSettings, 'field' | 'thicknessNm' | 'thicknessRangeNm' | 'swirlSpeed' | 'timeSeconds'>,
): number {
  if (s.field === 'uniform') return s.thicknessNm;
  let h = y;
  if (s.field === 'swirl') {
    // Swirling bands: the height is advected around the vertical axis by a slow, smooth flow.
    const t = s.timeSeconds * s.swirlSpeed;
    const azimuth = Math.atan2(z, x);
    h += 0.12 * Math.sin(3 * azimuth + 2 * h + t) + 0.07 * Math.sin(5 * azimuth - 3 * h - 1.7 * t) + 0.05 * Math.sin(9 * h + 0.6 * t);
  }
  // Gravity drains the film: thin at the top, thick at the bottom, down to a ~10 nm black film in a cap.
  const d = s.thicknessNm - 0.5 * s.thicknessRangeNm * clamp(h, -1, 1);
  const capped = Math.max(d, 10) + (10 - Math.max(d, 10)) * smoothstep(0.82, 0.95, y);
  return clamp(capped, FILM_STACK_DOMAIN.thicknessNm.min, FILM_STACK_DOMAIN.thicknessNm.max);
}

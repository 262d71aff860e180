import {
  DRAINED_FILM_SETTINGS,
  drainedFilmMaxNm,
  drainedFilmUniforms,
  drainedThicknessNm,
  updateDrainedFilmUniforms,
} from './drainedFilm.ts';
import { numberSetting, thicknessField } from './thicknessField.ts';

/**
 * The drained film stirred by a slow, smooth flow around the vertical axis
 * (shaders/fields/swirlField.glsl): the height is displaced by three travelling waves, by at
 * most 0.24, deterministic in time.
 */
export const swirlField = thicknessField({
  glsl: 'swirlField.glsl',
  settings: {
    ...DRAINED_FILM_SETTINGS,
    swirlSpeed: numberSetting('speed', { min: 0, max: 10, unit: '' }, 0.4, 0.05, 'film'),
  },
  reads: ['thicknessNm', 'timeSeconds'],
  uniforms: () => ({ ...drainedFilmUniforms(), uSwirlSpeed: { value: 0 }, uTimeSeconds: { value: 0 } }),
  update: (u, s) => {
    updateDrainedFilmUniforms(u, s);
    u.uSwirlSpeed!.value = s.swirlSpeed;
    u.uTimeSeconds!.value = s.timeSeconds;
  },
  thicknessAt: ([x, y, z], s) => {
    const t = s.timeSeconds * s.swirlSpeed;
    const azimuth = Math.atan2(z, x);
    const h =
      y + 0.12 * Math.sin(3 * azimuth + 2 * y + t) + 0.07 * Math.sin(5 * azimuth - 3 * y - 1.7 * t) + 0.05 * Math.sin(9 * y + 0.6 * t);
    return drainedThicknessNm(h, y, s);
  },
  // The swirl moves h by at most 0.24 beyond ±1, where the drained film is clamped.
  maxThicknessNm: drainedFilmMaxNm,
  animates: true,
  evolves: false,
});

import {
  DRAINED_FILM_SETTINGS,
  drainedFilmMaxNm,
  drainedFilmUniforms,
  drainedThicknessNm,
  updateDrainedFilmUniforms,
} from './drainedFilm.ts';
import { thicknessField } from './thicknessField.ts';

/** A film at rest after draining (shaders/fields/drainageField.glsl): the height alone sets it. */
export const drainageField = thicknessField({
  glsl: 'drainageField.glsl',
  settings: DRAINED_FILM_SETTINGS,
  reads: ['thicknessNm'],
  uniforms: drainedFilmUniforms,
  update: updateDrainedFilmUniforms,
  thicknessAt: ([, y], s) => drainedThicknessNm(y, y, s),
  maxThicknessNm: drainedFilmMaxNm,
  animates: false,
  evolves: false,
});

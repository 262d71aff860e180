import { drainedFilmMaxNm, drainedFilmUniforms, drainedThicknessNm, updateDrainedFilmUniforms } from './drainedFilm.ts';
import type { ThicknessField } from './thicknessField.ts';

/** A film at rest after draining (shaders/fields/drainageField.glsl): the height alone sets it. */
export const drainageField: ThicknessField = {
  glsl: 'drainageField.glsl',
  uniforms: drainedFilmUniforms,
  update: updateDrainedFilmUniforms,
  thicknessAt: ([, y], s) => drainedThicknessNm(y, y, s),
  maxThicknessNm: drainedFilmMaxNm,
  reads: ['thicknessNm', 'thicknessRangeNm'],
  animates: false,
};

import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { thicknessField } from './thicknessField.ts';

/** The same thickness everywhere (shaders/fields/uniformField.glsl): the reference views. */
export const uniformField = thicknessField({
  glsl: 'uniformField.glsl',
  settings: {},
  reads: ['thicknessNm'],
  uniforms: () => ({ uThicknessNm: { value: 500 } }),
  update: (u, s) => {
    u.uThicknessNm!.value = s.thicknessNm;
  },
  thicknessAt: (_, s) => s.thicknessNm,
  maxThicknessNm: (s) => Math.min(FILM_STACK_DOMAIN.thicknessNm.max, Math.max(s.thicknessNm, 1)),
  animates: false,
  evolves: false,
});

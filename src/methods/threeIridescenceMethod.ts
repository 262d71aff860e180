import type { FilmMethod } from './filmMethod.ts';

/**
 * `three-iridescence`: three.js's own iridescence (Belcour–Barla, `evalIridescence`), the
 * benchmark's peer: not offered to users.
 */
export const threeIridescenceMethod = {
  glsl: 'threeIridescenceMethod.glsl',
  reads: ['polarization'],
  offered: false,
} as const satisfies FilmMethod;

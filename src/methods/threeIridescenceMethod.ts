import type { FilmMethod } from './filmMethod.ts';

/**
 * `three-iridescence`: three.js's own iridescence (Belcour–Barla, `evalIridescence`), the
 * benchmark's peer: not offered to users. It models one film on a base: a stack of films is drawn
 * by the table instead.
 */
export const threeIridescenceMethod = {
  glsl: 'threeIridescenceMethod.glsl',
  reads: ['polarization'],
  offered: false,
  frameCost: { constant: 1, dispersive: 1 },
  fills: ['constant', 'dispersive'],
} as const satisfies FilmMethod;

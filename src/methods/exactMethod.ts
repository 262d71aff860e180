import type { FilmMethod } from './filmMethod.ts';

/**
 * `exact`: the binned spectral integral per fragment (paper eqs 15–18 over the film reflectance of
 * eqs 1–14), the accuracy reference among the methods.
 */
export const exactMethod = {
  glsl: 'exactMethod.glsl',
  reads: ['polarization', 'media', 'spectralBins'],
  offered: true,
} as const satisfies FilmMethod;

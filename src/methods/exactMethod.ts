import type { FilmMethod } from './filmMethod.ts';

/**
 * `exact`: the binned spectral integral per fragment (paper eqs 15–18 over the film reflectance of
 * eqs 1–14), the accuracy reference among the methods; a stack of films by the transfer-matrix
 * recursion per bin (shaders/physics/transferMatrix.glsl).
 */
export const exactMethod = {
  glsl: 'exactMethod.glsl',
  reads: ['polarization', 'media', 'spectralBins', 'stack'],
  offered: true,
  fills: ['constant', 'dispersive', 'stack'],
  frameCost: { constant: 1.5, dispersive: 2.5 },
} as const satisfies FilmMethod;

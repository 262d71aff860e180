import type { FilmMethod } from './filmMethod.ts';

/**
 * `fourier`: the Airy sum as a Fourier series in the optical path per fragment, a few lookups of
 * the light's spectral transform and nothing to build; the binned integral where the film has no
 * real optical path. A dispersive film or inside has no series in the path alone
 * (docs/physics.md#a-dispersive-film): its bins would cost hundreds of times a plain sphere per
 * fragment, while the table is filled from the same bins once per change, so the table is drawn
 * instead. A stack of films has no closed-form series either: the table is drawn for it too.
 */
export const fourierMethod = {
  glsl: 'fourierMethod.glsl',
  reads: ['polarization', 'media', 'spectralBins', 'spectralTransform'],
  offered: true,
  frameCost: { constant: 2, dispersive: 2.5 },
  fills: ['constant'],
} as const satisfies FilmMethod;

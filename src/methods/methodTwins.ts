import { fourierXyz } from '../physics/airySeries.ts';
import { type SpectralBins, binnedXyz } from '../physics/binnedIntegration.ts';
import type { FilmOptics } from '../physics/filmReflectance.ts';
import type { SpectralTransform } from '../physics/spectralTransform.ts';
import type { Xyz } from '../physics/spectralWeights.ts';
import type { FilmMethodName } from './methods.ts';

/** The light as a method's float64 twin takes it: the bins of the binned integral and the series' spectral transform. */
export interface TwinLight {
  readonly bins: SpectralBins;
  readonly transform: SpectralTransform;
}

/**
 * A method's float64 twin (src/physics): the XYZ its shader computes for one film at one thickness
 * and angle, from the film's optics, in float64.
 */
export type MethodTwin = (optics: FilmOptics, light: TwinLight) => Xyz;

/**
 * Each method's float64 twin, by the method's name (null: a peer with no twin in src/physics).
 * Kept apart from the registry's entries so that a material, which draws by the shader alone,
 * bundles none of the float64 integrals; the parity tests and the benchmark look twins up here.
 */
export const METHOD_TWINS: Readonly<Record<FilmMethodName, MethodTwin | null>> = {
  exact: (optics, light) => binnedXyz(optics, light.bins),
  // The table's texels are the exact integral (its binned fill); the lookup only interpolates between them.
  table: (optics, light) => binnedXyz(optics, light.bins),
  fourier: (optics, light) => fourierXyz(optics, light.transform, light.bins),
  'three-iridescence': null,
};

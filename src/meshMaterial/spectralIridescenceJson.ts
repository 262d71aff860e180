import { type MaterialJSON } from 'three';
import { ParameterError } from '../input/validate.ts';
import { type CheckedOptions, type SpectralIridescenceOptions } from './spectralIridescenceOptions.ts';

/** The `type` a spectral material's JSON gives, under which three's MaterialLoader is told to make a ThinFilmMaterial. */
export const THIN_FILM_MATERIAL_TYPE = 'ThinFilmMaterial';

/** A spectral material's JSON: three's for the physical material, and the film's options. */
export type SpectralMaterialJson = MaterialJSON & { readonly spectralIridescence: SpectralIridescenceOptions };

/**
 * A spectral material's JSON from three's for its physical material: typed as a ThinFilmMaterial's
 * (a MeshPhysicalMaterial whose film is spectral, which is what an upgraded material is too), with
 * the film's options as `spectralIridescence`, in the form the options are given in.
 */
export const spectralMaterialJson = (data: MaterialJSON, options: CheckedOptions): SpectralMaterialJson => ({
  ...data,
  type: THIN_FILM_MATERIAL_TYPE,
  spectralIridescence: JSON.parse(JSON.stringify(options)) as SpectralIridescenceOptions,
});

/**
 * The film's options in a material's JSON (unchecked: `spectralIridescence` checks them), or
 * undefined where it holds none; a ParameterError where they are not an object.
 */
export function filmOptionsOfJson(json: MaterialJSON): SpectralIridescenceOptions | undefined {
  const options = (json as Partial<SpectralMaterialJson>).spectralIridescence;
  if (options === undefined) return undefined;
  if (typeof options !== 'object' || options === null || Array.isArray(options))
    throw new ParameterError(
      'spectralIridescence',
      `spectralIridescence: ${JSON.stringify(options)} is not allowed; expected the film's options, an object`,
    );
  return options;
}

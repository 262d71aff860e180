import { type Material, type MaterialJSON, MeshPhysicalMaterial, type MeshPhysicalMaterialParameters, type Texture } from 'three';
import { spectralIridescence } from './spectralIridescence.ts';
import { copySpectralFilm, defineOptionProperties, filmOf } from './spectralFilm.ts';
import { type SpectralIridescenceOptions, type SpectralIridescenceProperties, splitFilmOptions } from './spectralIridescenceOptions.ts';
import { THIN_FILM_MATERIAL_TYPE, type SpectralMaterialJson, filmOptionsOfJson, spectralMaterialJson } from './spectralIridescenceJson.ts';

/** A physical material's parameters and the film's options, in one object. */
export type ThinFilmMaterialParameters = MeshPhysicalMaterialParameters & SpectralIridescenceOptions;

// The option properties, typed once in SpectralIridescenceProperties: the class and this interface
// merge, and defineOptionProperties (below) puts the accessors on the prototype from OPTION_NAMES.
// eslint-disable-next-line @typescript-eslint/no-unsafe-declaration-merging, @typescript-eslint/no-empty-object-type
export interface ThinFilmMaterial extends SpectralIridescenceProperties {}

/**
 * A MeshPhysicalMaterial whose iridescence is the spectral film from the start (iridescence 1
 * unless the parameters say otherwise), its options properties as three's are:
 * `new ThinFilmMaterial({ iridescenceIOR: 1.33, iridescenceThicknessMaximum: 450, mode: 'table', illuminant: 'D65' })`,
 * then `material.mode = 'fourier'`. Every parameter and option is checked (a ParameterError names
 * the first bad one); `clone()`, `copy()` and `toJSON()` carry the options, and three's
 * MaterialLoader loads it back once told of the class:
 * `MaterialLoader.registerMaterial(ThinFilmMaterial.type, ThinFilmMaterial)`.
 *
 * `ThinFilmMaterial.type` (the class's, as three's node materials name theirs) is
 * 'ThinFilmMaterial', and so is its JSON's `type`; an instance's `type` stays
 * 'MeshPhysicalMaterial', because three's WebGLRenderer picks the shader it draws a material with
 * by that name (WebGLPrograms' shaderIDs), and the shader is the physical material's.
 */
// eslint-disable-next-line @typescript-eslint/no-unsafe-declaration-merging -- the interface above: accessors made at load
export class ThinFilmMaterial extends MeshPhysicalMaterial {
  static readonly type = THIN_FILM_MATERIAL_TYPE;
  readonly isThinFilmMaterial = true;

  constructor(parameters: ThinFilmMaterialParameters = {}) {
    const [physical, film] = splitFilmOptions(parameters);
    super({ iridescence: 1, ...physical });
    spectralIridescence(this, film);
  }

  override copy(source: Material): this {
    super.copy(source);
    copySpectralFilm(this, source);
    return this;
  }

  override toJSON(meta?: Parameters<Material['toJSON']>[0]): SpectralMaterialJson {
    return spectralMaterialJson(super.toJSON(meta), filmOf(this)!.options);
  }

  /** three's, then the film's options from the JSON (checked as `spectralIridescence` checks them). */
  override fromJSON(json: MaterialJSON, textures: Record<string, Texture>): this {
    super.fromJSON(json, textures);
    const options = filmOptionsOfJson(json);
    if (options !== undefined) spectralIridescence(this, options);
    return this;
  }
}

defineOptionProperties(ThinFilmMaterial.prototype);

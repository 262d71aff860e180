import { type Material, MeshPhysicalMaterial, type MeshPhysicalMaterialParameters } from 'three';
import { type LinearRgb } from '../physics/artistMetal.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type Medium } from '../physics/medium.ts';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { type Normalization } from '../physics/spectralWeights.ts';
import { type FilmQuality, type FilmQualityOptions } from '../settings/filmQuality.ts';
import { copySpectralFilm, setSpectralOption, spectralIridescence, spectralOption } from './spectralIridescence.ts';
import {
  type BaseInput,
  type EdgeTintInput,
  type FilmMode,
  type SpectralIridescenceOptions,
  splitFilmOptions,
} from './spectralIridescenceOptions.ts';

/** A physical material's parameters and the film's options, in one object. */
export type ThinFilmMaterialParameters = MeshPhysicalMaterialParameters & SpectralIridescenceOptions;

/**
 * A MeshPhysicalMaterial whose iridescence is the spectral film from the start (iridescence 1
 * unless the parameters say otherwise), its options properties as three's are:
 * `new ThinFilmMaterial({ iridescenceIOR: 1.33, iridescenceThicknessMaximum: 450, mode: 'table', illuminant: 'D65' })`,
 * then `material.mode = 'fourier'`. Every parameter and option is checked (a ParameterError names
 * the first bad one); `clone()` and `copy()` carry the options.
 */
export class ThinFilmMaterial extends MeshPhysicalMaterial {
  readonly isThinFilmMaterial = true;

  constructor(parameters: ThinFilmMaterialParameters = {}) {
    super({ iridescence: 1, ...splitFilmOptions(parameters)[0] });
    spectralIridescence(this, splitFilmOptions(parameters)[1]);
  }

  get mode(): FilmMode {
    return spectralOption(this, 'mode');
  }
  set mode(value: FilmMode) {
    setSpectralOption(this, 'mode', value);
  }
  get illuminant(): IlluminantSpec {
    return spectralOption(this, 'illuminant');
  }
  set illuminant(value: IlluminantSpec) {
    setSpectralOption(this, 'illuminant', value);
  }
  get polarization(): Polarization {
    return spectralOption(this, 'polarization');
  }
  set polarization(value: Polarization) {
    setSpectralOption(this, 'polarization', value);
  }
  get normalization(): Normalization {
    return spectralOption(this, 'normalization');
  }
  set normalization(value: Normalization) {
    setSpectralOption(this, 'normalization', value);
  }
  get base(): Medium | null {
    return spectralOption(this, 'base');
  }
  /** a medium or its text (`'Ti'`, `'complex:2.6,3.4'`), or null for three's `ior` */
  set base(value: BaseInput | null) {
    setSpectralOption(this, 'base', value);
  }
  get film(): Medium | null {
    return spectralOption(this, 'film');
  }
  /** a medium or its text (`'TiO2'`, `'Fe3O4'`), or null for three's `iridescenceIOR` */
  set film(value: BaseInput | null) {
    setSpectralOption(this, 'film', value);
  }
  get edgeTint(): LinearRgb | null {
    return spectralOption(this, 'edgeTint');
  }
  /** a metal's edge tint (a Color, a hex number, linear [r, g, b]), or null for the base colour */
  set edgeTint(value: EdgeTintInput | null) {
    setSpectralOption(this, 'edgeTint', value);
  }
  get quality(): FilmQuality {
    return spectralOption(this, 'quality');
  }
  /** any of the knobs, over the defaults */
  set quality(value: FilmQualityOptions) {
    setSpectralOption(this, 'quality', value);
  }

  override copy(source: Material): this {
    super.copy(source);
    copySpectralFilm(this, source);
    return this;
  }
}

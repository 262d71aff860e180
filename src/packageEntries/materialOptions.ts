/**
 * What both material entries (`thin-film-color/material`, `thin-film-color/webgpu`) export alike:
 * the film's options and their types, the film's quality, the error a bad option raises, and
 * whether a material is spectral.
 */
export { isSpectralIridescence } from '../meshMaterial/spectralFilm.ts';
export {
  type BaseInput,
  type EdgeTintInput,
  type FilmMode,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
} from '../meshMaterial/spectralIridescenceOptions.ts';
export { DEFAULT_FILM_QUALITY, type FilmQuality, type FilmQualityOptions } from '../settings/filmQuality.ts';
export type { FilmTableLayout } from '../settings/filmTableLayout.ts';
export type { IlluminantSpec } from '../physics/illuminants.ts';
export type { LightTint } from '../physics/lightTint.ts';
export type { Medium } from '../physics/medium.ts';
export type { LinearRgb } from '../physics/artistMetal.ts';
export { ParameterError } from '../input/validate.ts';

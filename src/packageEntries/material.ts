/**
 * The library's material entry (`thin-film-color/material`): the spectral thin film for
 * three.js's MeshPhysicalMaterial (three.js is a peer dependency). How to use it: docs/material.md.
 */
export { spectralIridescence, useSpectralIridescence, whenSpectralReady } from '../meshMaterial/spectralIridescence.ts';
export { isSpectralIridescence } from '../meshMaterial/spectralFilm.ts';
export {
  type BaseInput,
  type EdgeTintInput,
  type FilmMode,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
} from '../meshMaterial/spectralIridescenceOptions.ts';
export { ThinFilmMaterial, type ThinFilmMaterialParameters } from '../meshMaterial/thinFilmMaterial.ts';
export { type SpectralMaterialJson } from '../meshMaterial/spectralIridescenceJson.ts';
export { DEFAULT_FILM_QUALITY, type FilmQuality, type FilmQualityOptions } from '../settings/filmQuality.ts';
export type { FilmTableLayout } from '../settings/filmTableLayout.ts';
export type { IlluminantSpec } from '../physics/illuminants.ts';
export type { Medium } from '../physics/medium.ts';
export type { LinearRgb } from '../physics/artistMetal.ts';
export { ParameterError } from '../input/validate.ts';

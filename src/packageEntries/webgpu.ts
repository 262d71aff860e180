/**
 * The library's WebGPU entry (`thin-film-color/webgpu`): the spectral thin film for three.js's
 * WebGPURenderer (`three/webgpu`, on its WebGPU and its WebGL2 backend), on a
 * MeshPhysicalNodeMaterial or a classic MeshPhysicalMaterial (three.js is a peer dependency). How
 * to use it: docs/material.md.
 */
export {
  type PhysicalMaterial,
  spectralIridescence,
  useSpectralIridescence,
  whenSpectralReady,
} from '../nodeMaterial/spectralNodeMaterial.ts';
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
export type { Medium } from '../physics/medium.ts';
export type { LinearRgb } from '../physics/artistMetal.ts';
export { ParameterError } from '../input/validate.ts';

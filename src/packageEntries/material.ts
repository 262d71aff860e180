/**
 * The library's material entry (`thin-film-color/material`): the spectral thin film for
 * three.js's MeshPhysicalMaterial (three.js is a peer dependency). How to use it: docs/material.md.
 */
export { spectralIridescence, useSpectralIridescence, whenSpectralReady } from '../meshMaterial/spectralIridescence.ts';
export { ThinFilmMaterial, type ThinFilmMaterialParameters } from '../meshMaterial/thinFilmMaterial.ts';
export { type SpectralMaterialJson } from '../meshMaterial/spectralIridescenceJson.ts';
export * from './materialOptions.ts';

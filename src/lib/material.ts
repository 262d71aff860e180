/**
 * The library's material entry (`thin-film-color/material`): the spectral thin film for
 * three.js's MeshPhysicalMaterial (three.js is a peer dependency). See README, "Use it in your
 * three.js scene".
 */
export {
  type SpectralIridescenceOptions,
  ThinFilmMaterial,
  isSpectralIridescence,
  spectralIridescence,
  useSpectralIridescence,
} from '../material/spectralIridescence.ts';
export { ParameterError } from '../physics/validate.ts';

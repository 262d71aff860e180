/**
 * The library's physics entry (`thin-film-color/physics`): the float64 reference, no DOM, no
 * three.js. A film's reflectance at one wavelength, its colour under a light, and the colour
 * conversions and difference the project uses.
 */
export {
  FILM_STACK_DOMAIN,
  type FilmStack,
  POLARIZATIONS,
  type Polarization,
  SOAP_FILM_IN_AIR,
  filmReflectance,
  filmTransmittance,
} from '../physics/filmReflectance.ts';
export { type ColorOptions, filmXyz, whiteXyz } from '../physics/spectralIntegration.ts';
export { NAMED_ILLUMINANTS, type IlluminantSpec } from '../physics/illuminants.ts';
export { LIGHT_TINT_DOMAIN, type LightTint } from '../physics/lightTint.ts';
export { NORMALIZATIONS, type Normalization, type Xyz } from '../physics/spectralWeights.ts';
export {
  type Matrix3,
  type Rgb,
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
  XYZ_TO_LINEAR_WIDE_GAMUT,
  applyMatrix3,
  encode8,
  mapToGamut,
  srgbDecode,
  srgbEncode,
  xyzToXy,
} from '../physics/colorConversions.ts';
export { deltaE00, xyzToLab } from '../physics/colorDifference.ts';
export { ParameterError } from '../input/validate.ts';

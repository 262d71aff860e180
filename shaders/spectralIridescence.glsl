// The spectral film inside three.js's MeshPhysicalMaterial (src/render/spectralIridescence.ts):
// the reflectance three's lights_fragment_begin takes from evalIridescence for the film over the
// dielectric base, computed instead as the film's XYZ (filmColor.glsl: eqs (1)–(18), every order
// of the Airy sum, under the chosen illuminant) taken to three's working space (linear sRGB,
// eq 19). The indices reach filmColor.glsl as uNOutside (1: three's film sits in air), uNFilm
// (iridescenceIOR) and uNInside (the material's ior, the base under the film).
#ifndef THIN_FILM_SPECTRAL_IRIDESCENCE
#define THIN_FILM_SPECTRAL_IRIDESCENCE

#include "filmColor.glsl"
#include "colorConversions.glsl"

uniform mat3 uXyzToLinearWorking;   // XYZ -> three.js's working space (linear sRGB, eq 19)

// Linear RGB reflectance relative to the light's white. Out-of-gamut components are kept, negative
// ones too (three clips its own film at 0): the working space is float, so a saturated film stays
// as saturated as the output space (Display P3, or sRGB's own clip at the end) allows. Clipping
// here moved saturated films by up to ΔE00 6.9 on the benchmark's grids.
vec3 spectralIridescence(float thicknessNm, float cosIncidence) {
  return applyMatrix3(uXyzToLinearWorking, filmXyz(thicknessNm, cosIncidence, false));
}

#endif

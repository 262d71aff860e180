// The spectral film inside three.js's MeshPhysicalMaterial (src/meshMaterial/spectralIridescence.ts,
// written into three's shader by src/meshMaterial/spectralFragmentShader.ts):
// the reflectance three's lights_fragment_begin takes from evalIridescence for the film over the
// dielectric base, computed instead as the film's XYZ (filmColor.glsl: eqs (1)–(18), every order
// of the Airy sum, under the chosen illuminant) taken to three's working space (linear sRGB,
// eq 19). The indices reach filmColor.glsl as uNOutside (1: three's film sits in air), uNFilm
// (iridescenceIOR) and uNInside (the material's ior, the base under the film).
#ifndef THIN_FILM_SPECTRAL_IRIDESCENCE
#define THIN_FILM_SPECTRAL_IRIDESCENCE

#include "filmColor.glsl"
#include "colorConversions.glsl"


#ifdef TFC_ENVIRONMENT_MATRIX
// The light's tint t: the film's matrix is the untinted light's, and three's lights are t's colour.
#include "filmLightTint.glsl"
// The film's environment matrix M in the working space at this fragment (tfcSpectralIridescence
// sets it; tfcEnvironmentThroughMatrix reads it).
mat3 tfcFilmMatrix = mat3(0.0);
#endif

// Linear RGB reflectance relative to the light's white. Out-of-gamut components are kept, negative
// ones too (three clips its own film at 0): the working space is float, so a saturated film stays
// as saturated as the output space (Display P3, or sRGB's own clip at the end) allows; clipping
// here would move saturated films (docs/material.md#the-films-f0-for-image-based-light). In a
// scene with an environment (TFC_ENVIRONMENT_MATRIX) it is M t, the film under the tinted light.
vec3 tfcSpectralIridescence(float thicknessNm, float cosIncidence) {
#ifdef TFC_ENVIRONMENT_MATRIX
  tfcFilmMatrix = uXyzToLinearWorking * tfcFilmXyz(thicknessNm, cosIncidence, false);
  return tfcFilmMatrix * uLightTint;
#else
  return tfcApplyMatrix3(uXyzToLinearWorking, tfcFilmXyz(thicknessNm, cosIncidence, false));
#endif
}

// The F0 three's image-based light takes for the film. three integrates a lobe's single scattering
// as Fss = F0·dfg.x + F90·dfg.y (its DFG table, at the roughness and n·v) and adds multiple
// scattering Fss·Favg·Ems / (1 − Ems·Favg), Ems = 1 − dfg.x − dfg.y, Favg = F0 + (1 − F0)/21
// (computeMultiscatteringIridescence): in all Fss / (1 − Ems·Favg). three gets F0 by inverting
// Schlick's curve at n·v. Here F0 solves Fss / (1 − Ems·Favg) = F, linear in F0:
//   F0 = (F·(1 − Ems/21) − F90·dfg.y) / (dfg.x + (20/21)·Ems·F),
// so the lobe reflects the film's own F under uniform light, at every angle. Schlick's inversion,
// or solving the single scattering alone (F0·dfg.x + F90·dfg.y = F·(dfg.x + dfg.y)), leaves the
// film off towards grazing, where the table departs from Schlick's curve and multiple scattering
// grows (docs/material.md#the-films-f0-for-image-based-light; the material's accuracy:
// docs/benchmarks.md). The denominator stays above 0.14 over three's table for F in −0.3–1.3.
vec3 tfcSpectralIridescenceF0(vec3 film, vec2 dfg, float f90) {
  float ems = 1.0 - dfg.x - dfg.y;
  return (film * (1.0 - ems / 21.0) - f90 * dfg.y) / max(dfg.x + (20.0 / 21.0) * ems * film, vec3(1e-4));
}

#ifdef TFC_ENVIRONMENT_MATRIX
// What the environment's light gains when the film reflects it as a spectrum: three's image-based
// light takes the film per channel, F L with F = M t; the film reflects M (t L), an integral of two
// spectra (docs/material.md#light). This is the difference, times `weight`: the film's weight
// (iridescence) times its lobe's share (1 - metalness for the dielectric lobe, metalness for the
// metallic). The light is what three's lobe integrates: the prefiltered radiance, and for the
// share of multiple scattering, Ems Favg, the cosine-weighted irradiance (computeMultiscatteringIridescence;
// Favg of the film's F0 averaged over the channels). On a smooth surface (Ems = 0) three's lobe
// reflects F L exactly (tfcSpectralIridescenceF0), and with this the surface reflects M (t L).
vec3 tfcEnvironmentThroughMatrix(vec3 radiance, vec3 irradiance, vec2 dfg, vec3 f0, float weight) {
  float ems = 1.0 - dfg.x - dfg.y;
  float favg = dot(f0 + (1.0 - f0) / 21.0, vec3(1.0 / 3.0));
  vec3 light = mix(radiance, irradiance * RECIPROCAL_PI, clamp(ems * favg, 0.0, 1.0));
  return weight * (tfcFilmMatrix * (uLightTint * light) - (tfcFilmMatrix * uLightTint) * light);
}
#endif

#endif

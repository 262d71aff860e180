// `three-iridescence` (src/methods/threeIridescenceMethod.ts): three.js's iridescence
// (Belcour–Barla, `evalIridescence`), the benchmark's peer. Its Rec.709 reflectance goes back to
// XYZ with the chunk's own matrix; the medium behind enters as baseF0 (0 for air: a soap bubble),
// as MeshPhysicalMaterial would pass it; a dispersive film enters as uNFilm, ñ_b at the sodium D line.
#ifndef THIN_FILM_THREE_IRIDESCENCE_METHOD
#define THIN_FILM_THREE_IRIDESCENCE_METHOD

#define USE_IRIDESCENCE
#include <common>
#include <iridescence_fragment>

TFC_FILM_COLOR tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  vec3 baseF0 = vec3(IorToFresnel0(nc.x, 1.0));
  vec3 rgb = evalIridescence(na, uNFilm.x, cosIncidence, thicknessNm, baseF0);
#ifdef TFC_ENVIRONMENT_MATRIX
  // three's film is an RGB triple: its reflection of colour c is the product rgb c, per channel.
  return inverse(XYZ_TO_REC709) * mat3(rgb.x, 0.0, 0.0, 0.0, rgb.y, 0.0, 0.0, 0.0, rgb.z);
#else
  return inverse(XYZ_TO_REC709) * rgb;
#endif
}

#endif

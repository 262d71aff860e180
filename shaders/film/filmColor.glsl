// The film's XYZ (with TFC_ENVIRONMENT_MATRIX its environment matrix: environmentMatrix.glsl) at a thickness and cos θ_i, by the method TFC_FILM_MODE selects: filmMethod.glsl
// is made from the methods' registry (src/methods/methods.ts), each method's own GLSL
// (shaders/methods/) under its named `#if`, so a program holds the one `tfcFilmXyzOf` it uses.
// fromInside swaps the outer and inner media (the far wall seen through the bubble); an opaque
// inside (TFC_OPAQUE_INSIDE) sends no light that way, so the film's XYZ from inside is 0.
#ifndef THIN_FILM_COLOR
#define THIN_FILM_COLOR

#include "environmentMatrix.glsl"
#include "filmMedia.glsl"
#include "filmWorkingSpace.glsl"
#include "filmMethod.glsl"

TFC_FILM_COLOR tfcFilmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
#ifdef TFC_OPAQUE_INSIDE
  if (fromInside) return TFC_FILM_COLOR(0.0);
#endif
  return tfcFilmXyzOf(thicknessNm, cosIncidence, fromInside);
}

#endif

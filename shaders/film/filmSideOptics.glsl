// The film's optics (eqs 1–14) for light from outside or from inside (filmMedia.glsl's sides), with
// the media at the sodium D line: for the methods that evaluate the film per fragment. Apart from
// filmMedia.glsl, which every method includes, so that a method without the polarisation's defines
// (`table`'s lookup) does not take filmReflectance.glsl.
#ifndef THIN_FILM_SIDE_OPTICS
#define THIN_FILM_SIDE_OPTICS
#include "filmReflectance.glsl"
#include "filmMedia.glsl"

FilmOptics tfcSideFilmOptics(bool fromInside, float thicknessNm, float cosIncidence) {
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  return tfcFilmOptics(na, uNFilm, nc, thicknessNm, cosIncidence);
}

#endif

// The film's three media (set by src/film/filmMedia.ts): the index outside (a, real: the light comes
// from a transparent medium), the film's (b) and the inside's (c) as vec2(n, k) for ñ = n + ik, at
// the sodium D line where they depend on λ (medium.glsl then holds ñ_b(λ) and ñ_c(λ)).
// TFC_OPAQUE_INSIDE: the inside absorbs (k > 0), so no light reaches the film from inside.
#ifndef THIN_FILM_MEDIA
#define THIN_FILM_MEDIA
uniform float uNOutside;
uniform vec2 uNFilm;
uniform vec2 uNInside;

// The light's n_a and the far side's ñ_c for light from outside, or from inside (a transparent inside).
void tfcFilmSides(bool fromInside, out float na, out vec2 nc) {
  na = fromInside ? uNInside.x : uNOutside;
  nc = fromInside ? vec2(uNOutside, 0.0) : uNInside;
}

#ifdef TFC_DISPERSIVE
#include "texelRecord.glsl"
// The film's and the inside's ñ = (n, k) in a knot of uMediaKnots (medium.glsl), a record of
// src/film/filmMedia.ts's MEDIA_KNOT read by its names.
void tfcKnotMedia(vec4 knot, out vec2 film, out vec2 inside) {
  vec4 record[TFC_MEDIA_KNOT_TEXELS] = vec4[TFC_MEDIA_KNOT_TEXELS](knot);
  film = TFC_RECORD_VEC2(record, TFC_MEDIA_KNOT_FILM);
  inside = TFC_RECORD_VEC2(record, TFC_MEDIA_KNOT_INSIDE);
}
#endif
#endif

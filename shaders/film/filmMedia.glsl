// The film's three media (set by src/film/filmMedia.ts): the index outside (a), the film's at the
// sodium D line (b; filmIndex.glsl holds a dispersive film's n_b(λ)), the index inside (c).
#ifndef THIN_FILM_MEDIA
#define THIN_FILM_MEDIA
uniform float uNOutside;
uniform float uNFilm;
uniform float uNInside;
#endif

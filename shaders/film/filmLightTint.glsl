// The light's tint t (linear sRGB relative to the light's white) where a film's colour is its
// environment matrix M (src/film/filmLightTint.ts sets it): M is the untinted light's, and t is one
// more colour it maps, M t the film under the tinted light.
#ifndef THIN_FILM_LIGHT_TINT
#define THIN_FILM_LIGHT_TINT

uniform vec3 uLightTint;

#endif

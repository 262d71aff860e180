// A new bubble after a burst (mirrors src/flow/renewFilm.ts, the GPU's own: the twin bursts once).
// uBurst (1 × 1, r) counts the steps since every rim of an opened hole reached the far side of the
// sphere, where no film is left; once it reaches uRenewSteps (0: never) the step that reads it
// puts the film back at its start (uStartFilm), closes the holes and counts from 0.
#ifndef THIN_FILM_RENEW_FILM
#define THIN_FILM_RENEW_FILM
#include "filmHoles.glsl"
uniform sampler2D uBurst;
uniform float uRenewSteps;

/** Whether this step renews the film. */
bool tfcRenewing() { return uRenewSteps > 0.0 && texelFetch(uBurst, ivec2(0), 0).r >= uRenewSteps; }

uniform sampler2D uHoles;

/** The burst's count (r) after this step's rims: one more while every ray of every open hole is at π, else 0. */
vec4 tfcBurstSteps() {
  if (tfcRenewing()) return vec4(0.0);
  bool opened = false;
  for (int s = 0; s < TFC_MAX_HOLES; s++) {
    if (!tfcReadHole(uHoles, s).open) continue;
    opened = true;
    for (int k = 0; k < TFC_HOLE_RAYS; k++)
      if (texelFetch(uHoles, ivec2(k, s), 0).r < TFC_HOLE_PI) return vec4(0.0);
  }
  return vec4(opened ? texelFetch(uBurst, ivec2(0), 0).r + 1.0 : 0.0, 0.0, 0.0, 0.0);
}
#endif

// A new bubble after a burst (mirrors src/gpuFilmDynamics/renewFilm.ts, the GPU's own: the twin bursts once).
// uBurst (1 × 1, a BURST record) counts the steps since every rim of an opened hole reached the far side of the
// sphere, where no film is left; once it reaches uRenewSteps (0: never) the step that reads it
// puts the film back at its start (uStartFilm), closes the holes and counts from 0.
#ifndef THIN_FILM_RENEW_FILM
#define THIN_FILM_RENEW_FILM
#include "filmHoles.glsl"
uniform sampler2D uBurst;
uniform float uRenewSteps;

/** The steps counted since no film was left. */
float tfcStepsSinceBurst(sampler2D burst) {
  vec4 steps = texelFetch(burst, ivec2(0), 0);
  return TFC_TEXEL_FLOAT(steps, TFC_BURST_STEPS);
}

/** Whether this step renews the film. */
bool tfcRenewing() { return uRenewSteps > 0.0 && tfcStepsSinceBurst(uBurst) >= uRenewSteps; }

/** The burst's texel after `steps` steps. */
vec4 tfcBurstTexel(float steps) {
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_BURST_STEPS, steps);
  return texel;
}

uniform sampler2D uHoles;

/** The burst's count after this step's rims: one more while every ray of every open hole is at π, else 0. */
vec4 tfcBurstSteps() {
  if (tfcRenewing()) return tfcBurstTexel(0.0);
  bool opened = false;
  for (int s = 0; s < TFC_MAX_HOLES; s++) {
    if (!tfcReadHole(uHoles, s).open) continue;
    opened = true;
    for (int k = 0; k < TFC_HOLE_RAYS; k++)
      if (tfcRayRadius(uHoles, k, s) < TFC_HOLE_PI) return tfcBurstTexel(0.0);
  }
  return tfcBurstTexel(opened ? tfcStepsSinceBurst(uBurst) + 1.0 : 0.0);
}
#endif

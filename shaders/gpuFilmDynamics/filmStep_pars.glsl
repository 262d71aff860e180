// What the passes of a step read of the film (src/gpuFilmDynamics/flowUniforms.ts makes these uniforms): the
// film (flowFilm.glsl) per cell of the cell atlas, the edge velocities u·n_e (EDGE_VELOCITY records)
// of the edge atlas, and the fixed step Δt (in R/U).
#ifndef THIN_FILM_FILM_STEP_PARS
#define THIN_FILM_FILM_STEP_PARS
#include "flowFilm.glsl"
uniform sampler2D uFilm;
uniform sampler2D uEdgeVelocity;
uniform float uDt;

/** The edge velocity u·n_e of the edge at `texel` of the edge atlas. */
float tfcEdgeVelocityAt(ivec2 texel) {
  vec4 velocity = texelFetch(uEdgeVelocity, texel, 0);
  return TFC_TEXEL_FLOAT(velocity, TFC_EDGE_VELOCITY_U);
}

/** An edge velocity's texel. */
vec4 tfcEdgeVelocityTexel(float u) {
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_EDGE_VELOCITY_U, u);
  return texel;
}
#endif

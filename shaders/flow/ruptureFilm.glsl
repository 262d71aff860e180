// GPU pass 8 of the step, its local part (mirrors rupturesHere and removeFilm of
// src/physics/flow/ruptureFilm.ts): an intact cell whose film is at or below the rupture thickness,
// or whose Γ would bring the tension to 0, loses its film (η = Γ = 0, no longer intact). The rims'
// growth (Taylor–Culick) is not ported: docs/flow.md#the-gpu-port. A cell-atlas pass.
#include "flowAtlas.glsl"
uniform sampler2D uFilm;
uniform float uRuptureEta;
uniform float uRuptureGamma;

vec4 tfcRuptureFilm() {
  vec4 film = texelFetch(uFilm, ivec2(gl_FragCoord.xy), 0);
  return film.b != 0.0 && (film.r <= uRuptureEta || film.g >= uRuptureGamma) ? vec4(0.0) : film;
}

// What the passes of a step read of the film (src/flow/flowUniforms.ts makes these uniforms): the
// film (η, Γ, intact, mark) per cell of the cell atlas, the edge velocities u·n_e (r) of the edge
// atlas, and the fixed step Δt (in R/U).
#ifndef THIN_FILM_FILM_STEP_PARS
#define THIN_FILM_FILM_STEP_PARS
uniform sampler2D uFilm;
uniform sampler2D uEdgeVelocity;
uniform float uDt;
#endif

// The passes of src/physics/flow/filmSimulation.ts that are its own: the film at its start (η, Γ
// from initialFilm, computed in float64 and uploaded; every cell intact), and evaporation, GPU pass
// 7: η ← max(0, η − eΔt) on intact cells, Γ untouched. Cell-atlas passes; the film is (η, Γ, intact, 0).
#include "flowAtlas.glsl"
#include "filmStep_pars.glsl"
/** e·Δt, the η every intact cell loses in one step. */
uniform float uEvaporationLoss;

vec4 tfcStartFilm() { return vec4(texelFetch(uFilm, ivec2(gl_FragCoord.xy), 0).rg, 1.0, 0.0); }

vec4 tfcEvaporate() {
  vec4 film = texelFetch(uFilm, ivec2(gl_FragCoord.xy), 0);
  if (film.b != 0.0) film.r = max(0.0, film.r - uEvaporationLoss);
  return film;
}

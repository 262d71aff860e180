// The passes of src/physics/filmDynamics/filmSimulation.ts that are its own: the film at its start (η, Γ
// from initialFilm, computed in float64 and uploaded as film texels, every cell intact:
// src/gpuFilmDynamics/paddedStart.ts's startFilmRecords), and evaporation, GPU pass 7: η ← max(0, η − eΔt)
// on intact cells, Γ untouched. Cell-atlas passes.
#include "flowAtlas.glsl"
#include "filmStep_pars.glsl"
/** e·Δt, the η every intact cell loses in one step. */
uniform float uEvaporationLoss;

vec4 tfcStartFilm() { return texelFetch(uFilm, ivec2(gl_FragCoord.xy), 0); }

vec4 tfcEvaporate() {
  TfcFilm film = tfcFilmAt(uFilm, ivec2(gl_FragCoord.xy));
  if (film.intact) film.eta = max(0.0, film.eta - uEvaporationLoss);
  return tfcFilmTexel(film);
}

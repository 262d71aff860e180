// GPU pass 6 of the step (mirrors src/physics/filmDynamics/transportFilm.ts): Dη/Dt = −η∇·u and
// DΓ/Dt = −Γ∇·u in conservation form by first-order upwind finite volumes, as three passes: each
// cell's limiter (the fraction of its outflow allowed, so no cell sends more than it holds), each
// edge's fluxes Δt_s L_e u_e q_upwind × limiter, and each cell's update, which keeps η, Γ ≥ 0;
// drawn once per sub-step of Δt_s = Δt/S (transportSubsteps in src/physics/filmDynamics/timeStep.ts).
#include "cubeSphereGrid.glsl"
#include "filmStep_pars.glsl"
/** Δt_s, the transport's sub-step (R/U). */
uniform float uTransportDt;

/** The cell's limiter: 1, or its content over its outflow in one step. */
vec4 tfcTransportLimiter() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  vec4 edges = tfcCellEdges(c);
  float outflow = 0.0;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    outflow += tfcEdgeCells(e).length * max(0.0, sign(edges[s]) * tfcEdgeVelocityAt(tfcEdgeTexel(e)));
  }
  outflow *= uTransportDt;
  float area = tfcCell(c).area;
  vec4 limiter = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(limiter, TFC_LIMITER_FRACTION, outflow > area ? area / outflow : 1.0);
  return limiter;
}

uniform sampler2D uLimiter;

/** The edge's fluxes of η and Γ from A to B (an edge-atlas pass). */
vec4 tfcTransportFlux() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  TfcEdgeCells cells = tfcEdgeCells(e);
  float u = tfcEdgeVelocityAt(tfcEdgeTexel(e));
  ivec2 upwind = tfcCellTexel(u >= 0.0 ? cells.a : cells.b);
  vec4 limiter = texelFetch(uLimiter, upwind, 0);
  float volume = uTransportDt * cells.length * u * TFC_TEXEL_FLOAT(limiter, TFC_LIMITER_FRACTION);
  TfcFilm film = tfcFilmAt(uFilm, upwind);
  vec4 flux = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(flux, TFC_FLUX_ETA, volume * film.eta);
  TFC_SET_TEXEL_FLOAT(flux, TFC_FLUX_GAMMA, volume * film.gamma);
  return flux;
}

uniform sampler2D uFlux;

/** The cell's η and Γ after the fluxes; whether it is intact kept. */
vec4 tfcTransportUpdate() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int c = tfcCellAt(texel);
  vec4 edges = tfcCellEdges(c);
  float etaOut = 0.0;
  float gammaOut = 0.0;
  for (int s = 0; s < 4; s++) {
    vec4 flux = texelFetch(uFlux, tfcEdgeTexel(tfcEdgeOf(edges[s])), 0);
    etaOut += sign(edges[s]) * TFC_TEXEL_FLOAT(flux, TFC_FLUX_ETA);
    gammaOut += sign(edges[s]) * TFC_TEXEL_FLOAT(flux, TFC_FLUX_GAMMA);
  }
  TfcFilm film = tfcFilmAt(uFilm, texel);
  float area = tfcCell(c).area;
  // max(0, ·) only absorbs rounding: the limiter already bounds the outflow by the content.
  film.eta = max(0.0, film.eta - etaOut / area);
  film.gamma = max(0.0, film.gamma - gammaOut / area);
  return tfcFilmTexel(film);
}

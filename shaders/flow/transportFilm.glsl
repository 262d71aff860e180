// GPU pass 6 of the step (mirrors src/physics/flow/transportFilm.ts): Dη/Dt = −η∇·u and
// DΓ/Dt = −Γ∇·u in conservation form by first-order upwind finite volumes, as three passes: each
// cell's limiter (the fraction of its outflow allowed, so no cell sends more than it holds), each
// edge's fluxes Δt_s L_e u_e q_upwind × limiter, and each cell's update, which keeps η, Γ ≥ 0;
// drawn once per sub-step of Δt_s = Δt/S (transportSubsteps in src/physics/flow/timeStep.ts).
#include "cubeSphereGrid.glsl"
#include "filmStep_pars.glsl"
/** Δt_s, the transport's sub-step (R/U). */
uniform float uTransportDt;

/** The cell's limiter (r): 1, or its content over its outflow in one step. */
vec4 tfcTransportLimiter() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  vec4 edges = tfcCellEdges(c);
  float outflow = 0.0;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    outflow += tfcEdgeCells(e).z * max(0.0, sign(edges[s]) * texelFetch(uEdgeVelocity, tfcEdgeTexel(e), 0).r);
  }
  outflow *= uTransportDt;
  float area = tfcCellGeometry(c).w;
  return vec4(outflow > area ? area / outflow : 1.0, 0.0, 0.0, 0.0);
}

uniform sampler2D uLimiter;

/** The edge's fluxes of η (r) and Γ (g) from A to B (an edge-atlas pass). */
vec4 tfcTransportFlux() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  vec4 cells = tfcEdgeCells(e);
  float u = texelFetch(uEdgeVelocity, tfcEdgeTexel(e), 0).r;
  ivec2 upwind = tfcCellTexel(tfcIndex(u >= 0.0 ? cells.x : cells.y));
  float volume = uTransportDt * cells.z * u * texelFetch(uLimiter, upwind, 0).r;
  return vec4(volume * texelFetch(uFilm, upwind, 0).rg, 0.0, 0.0);
}

uniform sampler2D uFlux;

/** The cell's η (r) and Γ (g) after the fluxes; its intact mark (b) kept. */
vec4 tfcTransportUpdate() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int c = tfcCellAt(texel);
  vec4 edges = tfcCellEdges(c);
  vec2 outflow = vec2(0.0);
  for (int s = 0; s < 4; s++) outflow += sign(edges[s]) * texelFetch(uFlux, tfcEdgeTexel(tfcEdgeOf(edges[s])), 0).rg;
  vec4 film = texelFetch(uFilm, texel, 0);
  // max(0, ·) only absorbs rounding: the limiter already bounds the outflow by the content.
  return vec4(max(vec2(0.0), film.rg - outflow / tfcCellGeometry(c).w), film.ba);
}

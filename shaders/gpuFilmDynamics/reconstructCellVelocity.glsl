// GPU pass 1 of the step (mirrors src/physics/filmDynamics/reconstructCellVelocity.ts): the tangent
// velocity at each cell centre from its 4 edge velocities, Perot's reconstruction
// u_c = (1/A_c) Σ_e L_e (u·n_out)_e (x_e − x_c), projected onto the tangent plane. A cell-atlas
// pass: a CELL_VELOCITY record per cell.
#include "cubeSphereGrid.glsl"
#include "filmStep_pars.glsl"

vec4 tfcReconstructCellVelocity() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  TfcCell cell = tfcCell(c);
  vec3 center = cell.center;
  vec4 edges = tfcCellEdges(c);
  vec3 u = vec3(0.0);
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    float flux = sign(edges[s]) * tfcEdgeVelocityAt(tfcEdgeTexel(e)) * tfcEdgeCells(e).length;
    u += flux * (tfcEdgeMid(e) - center);
  }
  u -= dot(u, center) * center;
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_VEC3(texel, TFC_CELL_VELOCITY_U, u / cell.area);
  return texel;
}

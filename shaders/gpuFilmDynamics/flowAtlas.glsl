// The cube-sphere's fields as texels (mirrors src/gpuFilmDynamics/flowAtlas.ts): the six faces side by side,
// three across and two down, in a cell atlas (faces of uFlowGridN² cells), a padded atlas (faces of
// (uFlowGridN + 2)², a ring of ghosts) and an edge atlas (edge e at (e mod 6N, e div 6N)). Indices
// held in float texels are whole numbers below 2²⁴, so they read back exactly.
#ifndef THIN_FILM_FLOW_ATLAS
#define THIN_FILM_FLOW_ATLAS
uniform int uFlowGridN;

ivec2 tfcFaceTexel(int side, int face, ivec2 ij) { return ivec2((face % 3) * side + ij.x, (face / 3) * side + ij.y); }

/** The texel of cell c = (face·n + j)·n + i. */
ivec2 tfcCellTexel(int c) {
  int n = uFlowGridN;
  int face = c / (n * n);
  int rest = c - face * n * n;
  return tfcFaceTexel(n, face, ivec2(rest % n, rest / n));
}

/** The cell a texel of the cell atlas holds. */
int tfcCellAt(ivec2 texel) {
  int n = uFlowGridN;
  int face = (texel.y / n) * 3 + texel.x / n;
  return (face * n + texel.y % n) * n + texel.x % n;
}

ivec2 tfcEdgeTexel(int e) { return ivec2(e % (6 * uFlowGridN), e / (6 * uFlowGridN)); }
int tfcEdgeAt(ivec2 texel) { return texel.y * 6 * uFlowGridN + texel.x; }

/** A whole number held in a float texel. */
int tfcIndex(float value) { return int(value + 0.5); }
#endif

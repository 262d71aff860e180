// The finite-volume mesh of the cube-sphere as textures (mirrors src/physics/filmDynamics/cubeSphereGrid.ts,
// uploaded from its float64 arrays by src/gpuFilmDynamics/flowGridTextures.ts, each texel a record of
// src/gpuFilmDynamics/flowTexels.ts): per cell its centre and area, its 4 sides' edges (±(e + 1): + where the
// cell is the edge's A) and neighbours; per edge its cells A and B, length, centre distance, normal,
// (z_B − z_A)/d and midpoint.
#ifndef THIN_FILM_CUBE_SPHERE_GRID
#define THIN_FILM_CUBE_SPHERE_GRID
#include "flowAtlas.glsl"
#include "texelRecord.glsl"
uniform sampler2D uCellGeometry;
uniform sampler2D uCellEdges;
uniform sampler2D uCellNeighbors;
uniform sampler2D uEdgeCells;
uniform sampler2D uEdgeNormal;
uniform sampler2D uEdgeMid;

struct TfcCell {
  /** The cell's centre (unit). */
  vec3 center;
  float area;
};

TfcCell tfcCell(int c) {
  vec4 texel = texelFetch(uCellGeometry, tfcCellTexel(c), 0);
  return TfcCell(TFC_TEXEL_VEC3(texel, TFC_CELL_GEOMETRY_CENTER), TFC_TEXEL_FLOAT(texel, TFC_CELL_GEOMETRY_AREA));
}
/** The edges of cell c's 4 sides, side s in [s], each ±(e + 1). */
vec4 tfcCellEdges(int c) {
  vec4 texel = texelFetch(uCellEdges, tfcCellTexel(c), 0);
  return TFC_TEXEL_VEC4(texel, TFC_CELL_EDGES_SIGNED_EDGES);
}
/** The cells across cell c's 4 sides, side s in [s]. */
vec4 tfcCellNeighbors(int c) {
  vec4 texel = texelFetch(uCellNeighbors, tfcCellTexel(c), 0);
  return TFC_TEXEL_VEC4(texel, TFC_CELL_NEIGHBORS_CELLS);
}
int tfcEdgeOf(float signedEdge) { return tfcIndex(abs(signedEdge)) - 1; }

struct TfcEdgeCells {
  int a;
  int b;
  float length;
  /** The distance between the centres of A and B. */
  float distance;
};

TfcEdgeCells tfcEdgeCells(int e) {
  vec4 texel = texelFetch(uEdgeCells, tfcEdgeTexel(e), 0);
  return TfcEdgeCells(
    tfcIndex(TFC_TEXEL_FLOAT(texel, TFC_EDGE_CELLS_A)),
    tfcIndex(TFC_TEXEL_FLOAT(texel, TFC_EDGE_CELLS_B)),
    TFC_TEXEL_FLOAT(texel, TFC_EDGE_CELLS_LENGTH),
    TFC_TEXEL_FLOAT(texel, TFC_EDGE_CELLS_DISTANCE)
  );
}
struct TfcEdgeNormal {
  /** The unit normal of the edge, from A to B. */
  vec3 normal;
  /** (z_B − z_A)/d. */
  float zSlope;
};

TfcEdgeNormal tfcEdgeNormal(int e) {
  vec4 texel = texelFetch(uEdgeNormal, tfcEdgeTexel(e), 0);
  return TfcEdgeNormal(TFC_TEXEL_VEC3(texel, TFC_EDGE_NORMAL_NORMAL), TFC_TEXEL_FLOAT(texel, TFC_EDGE_NORMAL_Z_SLOPE));
}
vec3 tfcEdgeMid(int e) {
  vec4 texel = texelFetch(uEdgeMid, tfcEdgeTexel(e), 0);
  return TFC_TEXEL_VEC3(texel, TFC_EDGE_MID_MID);
}
#endif

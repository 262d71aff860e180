// The finite-volume mesh of the cube-sphere as textures (mirrors src/physics/flow/cubeSphereGrid.ts,
// uploaded from its float64 arrays by src/flow/flowGridTextures.ts): per cell its centre and area,
// its 4 edges (±(e + 1): + where the cell is the edge's A) and neighbours; per edge its cells A and
// B, length, centre distance, normal, (z_B − z_A)/d and midpoint.
#ifndef THIN_FILM_CUBE_SPHERE_GRID
#define THIN_FILM_CUBE_SPHERE_GRID
#include "flowAtlas.glsl"
uniform sampler2D uCellGeometry;
uniform sampler2D uCellEdges;
uniform sampler2D uCellNeighbors;
uniform sampler2D uEdgeCells;
uniform sampler2D uEdgeNormal;
uniform sampler2D uEdgeMid;

/** Centre (xyz) and area (w) of cell c. */
vec4 tfcCellGeometry(int c) { return texelFetch(uCellGeometry, tfcCellTexel(c), 0); }
vec4 tfcCellEdges(int c) { return texelFetch(uCellEdges, tfcCellTexel(c), 0); }
vec4 tfcCellNeighbors(int c) { return texelFetch(uCellNeighbors, tfcCellTexel(c), 0); }
int tfcEdgeOf(float signedEdge) { return tfcIndex(abs(signedEdge)) - 1; }
/** Cells A and B (xy), length (z) and centre distance (w) of edge e. */
vec4 tfcEdgeCells(int e) { return texelFetch(uEdgeCells, tfcEdgeTexel(e), 0); }
/** Unit normal from A to B (xyz) and (z_B − z_A)/d (w) of edge e. */
vec4 tfcEdgeNormal(int e) { return texelFetch(uEdgeNormal, tfcEdgeTexel(e), 0); }
vec3 tfcEdgeMid(int e) { return texelFetch(uEdgeMid, tfcEdgeTexel(e), 0).xyz; }
#endif

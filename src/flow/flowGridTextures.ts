import type { DataTexture } from 'three';
import { floatTexture } from '../gpu/floatRow.ts';
import type { CubeSphereGrid } from '../physics/flow/cubeSphereGrid.ts';
import type { CubeSphereHalo } from '../physics/flow/cubeSphereSampler.ts';
import { cellTexelIndex, edgeAtlasSize, faceAtlasSize, paddedTexelIndex } from './flowAtlas.ts';

/** Texels per padded texel in the halo's tap table, two (cell, weight) taps each: a corner ghost needs 9 taps. */
export const HALO_TAP_TEXELS = 5;

/** The grid's uniforms (shaders/flow/cubeSphereGrid.glsl) and the halo's tap table, uploaded from the float64 grid. */
export type FlowGridTextures = Readonly<
  Record<'uCellGeometry' | 'uCellEdges' | 'uCellNeighbors' | 'uEdgeCells' | 'uEdgeNormal' | 'uEdgeMid' | 'uHaloTaps', DataTexture>
>;

/**
 * The mesh's geometry and connectivity as float textures (indices are whole numbers below 2²⁴, so
 * float32 holds them exactly); the geometry is rounded once from float64.
 */
export function flowGridTextures(grid: CubeSphereGrid, halo: CubeSphereHalo): FlowGridTextures {
  const n = grid.n;
  const cells = faceAtlasSize(n);
  const edges = edgeAtlasSize(n);
  const cellData = () => new Float32Array(4 * cells.width * cells.height);
  const [geometry, cellEdges, neighbors] = [cellData(), cellData(), cellData()];
  for (let c = 0; c < grid.cellCount; c++) {
    const t = 4 * cellTexelIndex(n, c);
    geometry.set([grid.center[3 * c]!, grid.center[3 * c + 1]!, grid.center[3 * c + 2]!, grid.area[c]!], t);
    for (let s = 0; s < 4; s++) {
      cellEdges[t + s] = grid.cellEdgeSign[4 * c + s]! * (grid.cellEdge[4 * c + s]! + 1);
      neighbors[t + s] = grid.cellNeighbor[4 * c + s]!;
    }
  }
  const edgeData = () => new Float32Array(4 * edges.width * edges.height);
  const [edgeCells, normal, mid] = [edgeData(), edgeData(), edgeData()];
  for (let e = 0; e < grid.edgeCount; e++) {
    const [a, b, d] = [grid.edgeA[e]!, grid.edgeB[e]!, grid.edgeDistance[e]!];
    edgeCells.set([a, b, grid.edgeLength[e]!, d], 4 * e);
    const dz = (grid.center[3 * b + 2]! - grid.center[3 * a + 2]!) / d;
    normal.set([grid.edgeNormal[3 * e]!, grid.edgeNormal[3 * e + 1]!, grid.edgeNormal[3 * e + 2]!, dz], 4 * e);
    mid.set([grid.edgeMid[3 * e]!, grid.edgeMid[3 * e + 1]!, grid.edgeMid[3 * e + 2]!, 0], 4 * e);
  }
  const padded = faceAtlasSize(n + 2);
  const taps = new Float32Array(4 * HALO_TAP_TEXELS * padded.width * padded.height);
  /** The taps of padded index p: (cell, weight) pairs. */
  const tapsOf = new Map<number, [number, number][]>();
  halo.paddedCell.forEach((c, p) => c >= 0 && tapsOf.set(p, [[c, 1]]));
  for (let g = 0; g < halo.ghostPadded.length; g++) {
    tapsOf.set(
      halo.ghostPadded[g]!,
      [0, 1, 2, 3].map((t) => [halo.ghostCells[4 * g + t]!, halo.ghostWeights[4 * g + t]!]),
    );
  }
  for (let g = 0; g < halo.cornerGhosts.length; g += 4) {
    const [p, a, b, c] = [halo.cornerGhosts[g]!, halo.cornerGhosts[g + 1]!, halo.cornerGhosts[g + 2]!, halo.cornerGhosts[g + 3]!];
    const corner = tapsOf.get(c)![0]![0];
    tapsOf.set(p, [...tapsOf.get(a)!, ...tapsOf.get(b)!, [corner, -1]]);
  }
  for (const [p, list] of tapsOf) {
    const base = 4 * HALO_TAP_TEXELS * paddedTexelIndex(n, p);
    list.forEach(([cell, weight], k) => taps.set([cell, weight], base + 2 * k));
  }
  return {
    uCellGeometry: floatTexture(geometry, cells.width, cells.height),
    uCellEdges: floatTexture(cellEdges, cells.width, cells.height),
    uCellNeighbors: floatTexture(neighbors, cells.width, cells.height),
    uEdgeCells: floatTexture(edgeCells, edges.width, edges.height),
    uEdgeNormal: floatTexture(normal, edges.width, edges.height),
    uEdgeMid: floatTexture(mid, edges.width, edges.height),
    uHaloTaps: floatTexture(taps, HALO_TAP_TEXELS * padded.width, padded.height),
  };
}

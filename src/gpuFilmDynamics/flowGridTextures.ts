import type { DataTexture } from 'three';
import { floatTexture } from '../gpu/floatRow.ts';
import { packTexelRecord } from '../gpu/texelRecord.ts';
import type { CubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import type { CubeSphereHalo } from '../physics/filmDynamics/cubeSphereSampler.ts';
import { cellTexelIndex, edgeAtlasSize, faceAtlasSize, paddedTexelIndex } from './flowAtlas.ts';
import { CELL_EDGES, CELL_GEOMETRY, CELL_NEIGHBORS, EDGE_CELLS, EDGE_MID, EDGE_NORMAL, HALO_TAPS } from './flowTexels.ts';

/** Texels per padded texel in the halo's tap table, each a HALO_TAPS record of two taps: a corner ghost needs 9 taps. */
export const HALO_TAP_TEXELS = 5;

/** The grid's uniforms (shaders/gpuFilmDynamics/cubeSphereGrid.glsl) and the halo's tap table, uploaded from the float64 grid. */
export type FlowGridTextures = Readonly<
  Record<'uCellGeometry' | 'uCellEdges' | 'uCellNeighbors' | 'uEdgeCells' | 'uEdgeNormal' | 'uEdgeMid' | 'uHaloTaps', DataTexture>
>;

/**
 * The mesh's geometry and connectivity as float textures (indices are whole numbers below 2²⁴, so
 * float32 holds them exactly); the geometry is rounded once from float64.
 */
export function flowGridTextures(grid: CubeSphereGrid, halo: CubeSphereHalo): FlowGridTextures {
  return { ...cellTextures(grid), ...edgeTextures(grid), uHaloTaps: haloTapTexture(grid.n, halo) };
}

/** Per cell of the cell atlas: its geometry, its sides' edges and its neighbours. */
function cellTextures(grid: CubeSphereGrid): Pick<FlowGridTextures, 'uCellGeometry' | 'uCellEdges' | 'uCellNeighbors'> {
  const { n } = grid;
  const cells = faceAtlasSize(n);
  const cellData = () => new Float32Array(4 * cells.width * cells.height);
  const [geometry, cellEdges, neighbors] = [cellData(), cellData(), cellData()];
  const sides = (c: number, of: (k: number) => number) => [of(4 * c), of(4 * c + 1), of(4 * c + 2), of(4 * c + 3)] as const;
  for (let c = 0; c < grid.cellCount; c++) {
    const t = cellTexelIndex(n, c);
    const center = [grid.center[3 * c]!, grid.center[3 * c + 1]!, grid.center[3 * c + 2]!] as const;
    packTexelRecord(CELL_GEOMETRY, geometry, t, { CENTER: center, AREA: grid.area[c]! });
    packTexelRecord(CELL_EDGES, cellEdges, t, { SIGNED_EDGES: sides(c, (k) => grid.cellEdgeSign[k]! * (grid.cellEdge[k]! + 1)) });
    packTexelRecord(CELL_NEIGHBORS, neighbors, t, { CELLS: sides(c, (k) => grid.cellNeighbor[k]!) });
  }
  return {
    uCellGeometry: floatTexture(geometry, cells.width, cells.height),
    uCellEdges: floatTexture(cellEdges, cells.width, cells.height),
    uCellNeighbors: floatTexture(neighbors, cells.width, cells.height),
  };
}

/** Per edge of the edge atlas: its cells, length and distance; its normal and slope; its midpoint. */
function edgeTextures(grid: CubeSphereGrid): Pick<FlowGridTextures, 'uEdgeCells' | 'uEdgeNormal' | 'uEdgeMid'> {
  const edges = edgeAtlasSize(grid.n);
  const edgeData = () => new Float32Array(4 * edges.width * edges.height);
  const [edgeCells, normal, mid] = [edgeData(), edgeData(), edgeData()];
  const vector = (v: Float64Array, e: number) => [v[3 * e]!, v[3 * e + 1]!, v[3 * e + 2]!] as const;
  for (let e = 0; e < grid.edgeCount; e++) {
    const [a, b, d] = [grid.edgeA[e]!, grid.edgeB[e]!, grid.edgeDistance[e]!];
    packTexelRecord(EDGE_CELLS, edgeCells, e, { A: a, B: b, LENGTH: grid.edgeLength[e]!, DISTANCE: d });
    const slope = (grid.center[3 * b + 2]! - grid.center[3 * a + 2]!) / d;
    packTexelRecord(EDGE_NORMAL, normal, e, { NORMAL: vector(grid.edgeNormal, e), Z_SLOPE: slope });
    packTexelRecord(EDGE_MID, mid, e, { MID: vector(grid.edgeMid, e) });
  }
  return {
    uEdgeCells: floatTexture(edgeCells, edges.width, edges.height),
    uEdgeNormal: floatTexture(normal, edges.width, edges.height),
    uEdgeMid: floatTexture(mid, edges.width, edges.height),
  };
}

/** The halo's taps of padded index p: (cell, weight) pairs, a cell's own or a ghost's (a corner ghost g₁ + g₂ − c). */
function haloTaps(halo: CubeSphereHalo): Map<number, [number, number][]> {
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
  return tapsOf;
}

/** The halo's tap table: HALO_TAP_TEXELS HALO_TAPS records per padded texel, the taps in order (unused ones weigh 0). */
function haloTapTexture(n: number, halo: CubeSphereHalo): DataTexture {
  const padded = faceAtlasSize(n + 2);
  const taps = new Float32Array(4 * HALO_TAP_TEXELS * padded.width * padded.height);
  for (const [p, list] of haloTaps(halo)) {
    const first = HALO_TAP_TEXELS * paddedTexelIndex(n, p);
    for (let k = 0; k < list.length; k += 2) {
      const [[cell0, weight0], [cell1, weight1] = [0, 0]] = [list[k]!, list[k + 1]];
      packTexelRecord(HALO_TAPS, taps, first + k / 2, { CELL_0: cell0, WEIGHT_0: weight0, CELL_1: cell1, WEIGHT_1: weight1 });
    }
  }
  return floatTexture(taps, HALO_TAP_TEXELS * padded.width, padded.height);
}

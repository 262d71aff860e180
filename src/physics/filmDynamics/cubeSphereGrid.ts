import { type FacePoint, faceDirection, facePoint, gnomonicSolidAngle } from './cubeSphereFaces.ts';

/**
 * The finite-volume mesh of the unit sphere: 6 faces of n × n equiangular cells (cell
 * (face, i, j) has index (face·n + j)·n + i) and the 12 n² edges between them, each stored once
 * with the cells A and B on its two sides. Cells are spherical quadrilaterals bounded by great
 * circles, so areas, edge lengths and edge normals are exact. docs/flow.md#the-grid.
 */
export interface CubeSphereGrid {
  readonly n: number;
  readonly cellCount: number;
  /** Unit vector of each cell's centre (the point at its centre angles), 3 per cell. */
  readonly center: Float64Array;
  /** Each cell's exact area (steradians); they sum to 4π. */
  readonly area: Float64Array;
  readonly edgeCount: number;
  readonly edgeA: Int32Array;
  readonly edgeB: Int32Array;
  /** Arc length of each edge. */
  readonly edgeLength: Float64Array;
  /** Great-circle distance between the centres of A and B. */
  readonly edgeDistance: Float64Array;
  /** Unit normal of each edge's great circle, tangent to the sphere, pointing from A to B, 3 per edge. */
  readonly edgeNormal: Float64Array;
  /** Unit vector of each edge's midpoint, 3 per edge. */
  readonly edgeMid: Float64Array;
  /** The 4 edges of each cell, 4 per cell. */
  readonly cellEdge: Int32Array;
  /** +1 where the cell is the edge's A (the normal points out of it), −1 where it is B. */
  readonly cellEdgeSign: Float64Array;
  /** The cell across each of the 4 edges. */
  readonly cellNeighbor: Int32Array;
  /** The smallest distance between neighbouring centres (bounds the time step by the elastic waves). */
  readonly minSpacing: number;
  /** The mean distance between neighbouring centres over the edges (bounds the time step by advection). */
  readonly meanSpacing: number;
}

const QUARTER_PI = Math.PI / 4;

/** The angle between unit vectors a and b, accurate at small angles. */
function angleBetween(a: Float64Array, ai: number, b: Float64Array, bi: number): number {
  const cx = a[ai + 1]! * b[bi + 2]! - a[ai + 2]! * b[bi + 1]!;
  const cy = a[ai + 2]! * b[bi]! - a[ai]! * b[bi + 2]!;
  const cz = a[ai]! * b[bi + 1]! - a[ai + 1]! * b[bi]!;
  return Math.atan2(Math.hypot(cx, cy, cz), a[ai]! * b[bi]! + a[ai + 1]! * b[bi + 1]! + a[ai + 2]! * b[bi + 2]!);
}

/** The cell containing a direction. */
export function cellOf(n: number, x: number, y: number, z: number, scratch: FacePoint): number {
  const p = facePoint(x, y, z, scratch);
  const step = (2 * QUARTER_PI) / n;
  const i = Math.min(n - 1, Math.max(0, Math.floor((Math.atan(p.tanA) + QUARTER_PI) / step)));
  const j = Math.min(n - 1, Math.max(0, Math.floor((Math.atan(p.tanB) + QUARTER_PI) / step)));
  return (p.face * n + j) * n + i;
}

const gridCache = new Map<number, CubeSphereGrid>();

/** The grid with n cells per face side (built once per n and shared; it is read-only). */
export function cubeSphereGrid(n: number): CubeSphereGrid {
  const cached = gridCache.get(n);
  if (cached) return cached;
  const grid = buildGrid(n);
  gridCache.set(n, grid);
  return grid;
}

/** The cells' centres and exact areas, and the corners of every face. */
interface GridCells {
  readonly center: Float64Array;
  readonly area: Float64Array;
  /** Corner (k, l) of each face, k, l ∈ [0, n], at cornerIndex. */
  readonly corner: Float64Array;
}

/** The place in GridCells.corner of corner (k, l) of face f. */
const cornerIndex = (n: number, f: number, k: number, l: number): number => 3 * ((f * (n + 1) + l) * (n + 1) + k);

/** The side s (−i, +i, −j, +j) of cell (f, i, j) as a pair of corners. */
function sideCorners(n: number, f: number, i: number, j: number, s: number): [number, number] {
  if (s === 0) return [cornerIndex(n, f, i, j), cornerIndex(n, f, i, j + 1)];
  if (s === 1) return [cornerIndex(n, f, i + 1, j), cornerIndex(n, f, i + 1, j + 1)];
  if (s === 2) return [cornerIndex(n, f, i, j), cornerIndex(n, f, i + 1, j)];
  return [cornerIndex(n, f, i, j + 1), cornerIndex(n, f, i + 1, j + 1)];
}

/** Cell c's face and (i, j) on it. */
const cellPlace = (n: number, c: number): [number, number, number] => [Math.floor(c / (n * n)), c % n, Math.floor(c / n) % n];

function gridCells(n: number): GridCells {
  const cellCount = 6 * n * n;
  const step = (2 * QUARTER_PI) / n;
  const tanAt = (k: number) => Math.tan(-QUARTER_PI + k * step);
  const center = new Float64Array(3 * cellCount);
  const area = new Float64Array(cellCount);
  const corner = new Float64Array(6 * (n + 1) * (n + 1) * 3);
  for (let f = 0; f < 6; f++) {
    for (let l = 0; l <= n; l++) for (let k = 0; k <= n; k++) faceDirection(f, tanAt(k), tanAt(l), corner, cornerIndex(n, f, k, l));
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const c = (f * n + j) * n + i;
        faceDirection(f, tanAt(i + 0.5), tanAt(j + 0.5), center, 3 * c);
        const [x0, x1, y0, y1] = [tanAt(i), tanAt(i + 1), tanAt(j), tanAt(j + 1)];
        area[c] = gnomonicSolidAngle(x1, y1) - gnomonicSolidAngle(x0, y1) - gnomonicSolidAngle(x1, y0) + gnomonicSolidAngle(x0, y0);
      }
    }
  }
  return { center, area, corner };
}

/**
 * The cell across each side of each cell. Halfway from the side's midpoint towards the
 * neighbour's centre lies inside the neighbour, on this face or the next.
 */
function cellNeighbors(n: number, { center, corner }: GridCells): Int32Array {
  const cellCount = 6 * n * n;
  const cellNeighbor = new Int32Array(4 * cellCount);
  const scratch: FacePoint = { face: 0, tanA: 0, tanB: 0 };
  for (let c = 0; c < cellCount; c++) {
    const [f, i, j] = cellPlace(n, c);
    for (let s = 0; s < 4; s++) {
      const [p, q] = sideCorners(n, f, i, j, s);
      const mx = corner[p]! + corner[q]!;
      const my = corner[p + 1]! + corner[q + 1]!;
      const mz = corner[p + 2]! + corner[q + 2]!;
      const mr = Math.hypot(mx, my, mz);
      const cx = center[3 * c]!;
      const cy = center[3 * c + 1]!;
      const cz = center[3 * c + 2]!;
      cellNeighbor[4 * c + s] = cellOf(n, (1.5 * mx) / mr - 0.5 * cx, (1.5 * my) / mr - 0.5 * cy, (1.5 * mz) / mr - 0.5 * cz, scratch);
    }
  }
  return cellNeighbor;
}

type GridEdges = Pick<
  CubeSphereGrid,
  'edgeA' | 'edgeB' | 'edgeLength' | 'edgeDistance' | 'edgeNormal' | 'edgeMid' | 'cellEdge' | 'cellEdgeSign'
>;

/** Edge e's geometry between cells a and b, its side the corners p and q: length, centre distance, midpoint and normal from a to b. */
function edgeGeometry(
  edges: GridEdges,
  e: number,
  { center, corner }: GridCells,
  [a, b]: [number, number],
  [p, q]: [number, number],
): void {
  edges.edgeLength[e] = angleBetween(corner, p, corner, q);
  edges.edgeDistance[e] = angleBetween(center, 3 * a, center, 3 * b);
  const mx = corner[p]! + corner[q]!;
  const my = corner[p + 1]! + corner[q + 1]!;
  const mz = corner[p + 2]! + corner[q + 2]!;
  const mr = Math.hypot(mx, my, mz);
  edges.edgeMid[3 * e] = mx / mr;
  edges.edgeMid[3 * e + 1] = my / mr;
  edges.edgeMid[3 * e + 2] = mz / mr;
  const nx = corner[p + 1]! * corner[q + 2]! - corner[p + 2]! * corner[q + 1]!;
  const ny = corner[p + 2]! * corner[q]! - corner[p]! * corner[q + 2]!;
  const nz = corner[p]! * corner[q + 1]! - corner[p + 1]! * corner[q]!;
  const towardsB =
    nx * (center[3 * b]! - center[3 * a]!) +
    ny * (center[3 * b + 1]! - center[3 * a + 1]!) +
    nz * (center[3 * b + 2]! - center[3 * a + 2]!);
  const scale = (towardsB >= 0 ? 1 : -1) / Math.hypot(nx, ny, nz);
  edges.edgeNormal[3 * e] = nx * scale;
  edges.edgeNormal[3 * e + 1] = ny * scale;
  edges.edgeNormal[3 * e + 2] = nz * scale;
}

/** Each edge once, from its lower-numbered cell (A), entered in both cells' lists. */
function gridEdges(n: number, cells: GridCells, cellNeighbor: Int32Array): GridEdges {
  const [cellCount, edgeCount] = [6 * n * n, 12 * n * n];
  const [edgeA, edgeB] = [new Int32Array(edgeCount), new Int32Array(edgeCount)];
  const [edgeLength, edgeDistance] = [new Float64Array(edgeCount), new Float64Array(edgeCount)];
  const [edgeNormal, edgeMid] = [new Float64Array(3 * edgeCount), new Float64Array(3 * edgeCount)];
  const [cellEdge, cellEdgeSign] = [new Int32Array(4 * cellCount), new Float64Array(4 * cellCount)];
  const edges: GridEdges = { edgeA, edgeB, edgeLength, edgeDistance, edgeNormal, edgeMid, cellEdge, cellEdgeSign };
  let e = 0;
  for (let c = 0; c < cellCount; c++) {
    const [f, i, j] = cellPlace(n, c);
    for (let s = 0; s < 4; s++) {
      const nb = cellNeighbor[4 * c + s]!;
      if (nb < c) continue;
      [edgeA[e], edgeB[e]] = [c, nb];
      edgeGeometry(edges, e, cells, [c, nb], sideCorners(n, f, i, j, s));
      [cellEdge[4 * c + s], cellEdgeSign[4 * c + s]] = [e, 1];
      const back = [0, 1, 2, 3].find((t) => cellNeighbor[4 * nb + t] === c);
      if (back === undefined) throw new Error(`cube-sphere grid ${n}: cell ${nb} does not border cell ${c}`);
      [cellEdge[4 * nb + back], cellEdgeSign[4 * nb + back]] = [e, -1];
      e++;
    }
  }
  if (e !== edgeCount) throw new Error(`cube-sphere grid ${n}: ${e} edges, expected ${edgeCount}`);
  return edges;
}

function buildGrid(n: number): CubeSphereGrid {
  const cells = gridCells(n);
  const cellNeighbor = cellNeighbors(n, cells);
  const edges = gridEdges(n, cells, cellNeighbor);
  const edgeCount = 12 * n * n;
  let minSpacing = Infinity;
  let spacingSum = 0;
  for (let e = 0; e < edgeCount; e++) {
    minSpacing = Math.min(minSpacing, edges.edgeDistance[e]!);
    spacingSum += edges.edgeDistance[e]!;
  }
  return {
    n,
    cellCount: 6 * n * n,
    center: cells.center,
    area: cells.area,
    edgeCount,
    ...edges,
    cellNeighbor,
    minSpacing,
    meanSpacing: spacingSum / edgeCount,
  };
}

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

function buildGrid(n: number): CubeSphereGrid {
  const cellCount = 6 * n * n;
  const step = (2 * QUARTER_PI) / n;
  const tanAt = (k: number) => Math.tan(-QUARTER_PI + k * step);
  const center = new Float64Array(3 * cellCount);
  const area = new Float64Array(cellCount);
  /** Corner (k, l) of each face, k, l ∈ [0, n]. */
  const corner = new Float64Array(6 * (n + 1) * (n + 1) * 3);
  const cornerIndex = (f: number, k: number, l: number) => 3 * ((f * (n + 1) + l) * (n + 1) + k);
  for (let f = 0; f < 6; f++) {
    for (let l = 0; l <= n; l++) for (let k = 0; k <= n; k++) faceDirection(f, tanAt(k), tanAt(l), corner, cornerIndex(f, k, l));
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const c = (f * n + j) * n + i;
        faceDirection(f, tanAt(i + 0.5), tanAt(j + 0.5), center, 3 * c);
        const [x0, x1, y0, y1] = [tanAt(i), tanAt(i + 1), tanAt(j), tanAt(j + 1)];
        area[c] = gnomonicSolidAngle(x1, y1) - gnomonicSolidAngle(x0, y1) - gnomonicSolidAngle(x1, y0) + gnomonicSolidAngle(x0, y0);
      }
    }
  }
  const edgeCount = 12 * n * n;
  const edgeA = new Int32Array(edgeCount);
  const edgeB = new Int32Array(edgeCount);
  const edgeLength = new Float64Array(edgeCount);
  const edgeDistance = new Float64Array(edgeCount);
  const edgeNormal = new Float64Array(3 * edgeCount);
  const edgeMid = new Float64Array(3 * edgeCount);
  const cellEdge = new Int32Array(4 * cellCount);
  const cellEdgeSign = new Float64Array(4 * cellCount);
  const cellNeighbor = new Int32Array(4 * cellCount);
  const scratch: FacePoint = { face: 0, tanA: 0, tanB: 0 };
  /** The sides −i, +i, −j, +j of a cell as pairs of corners. */
  const sideCorners = (f: number, i: number, j: number, s: number): [number, number] =>
    s === 0
      ? [cornerIndex(f, i, j), cornerIndex(f, i, j + 1)]
      : s === 1
        ? [cornerIndex(f, i + 1, j), cornerIndex(f, i + 1, j + 1)]
        : s === 2
          ? [cornerIndex(f, i, j), cornerIndex(f, i + 1, j)]
          : [cornerIndex(f, i, j + 1), cornerIndex(f, i + 1, j + 1)];
  // Pass 1: the neighbour across each side. Halfway from the side's midpoint towards the
  // neighbour's centre lies inside the neighbour, on this face or the next.
  for (let c = 0; c < cellCount; c++) {
    const [f, i, j] = [Math.floor(c / (n * n)), c % n, Math.floor(c / n) % n];
    for (let s = 0; s < 4; s++) {
      const [p, q] = sideCorners(f, i, j, s);
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
  // Pass 2: each edge once, from its lower-numbered cell (A), entered in both cells' lists.
  let edges = 0;
  for (let c = 0; c < cellCount; c++) {
    const [f, i, j] = [Math.floor(c / (n * n)), c % n, Math.floor(c / n) % n];
    for (let s = 0; s < 4; s++) {
      const nb = cellNeighbor[4 * c + s]!;
      if (nb < c) continue;
      const e = edges++;
      const [p, q] = sideCorners(f, i, j, s);
      edgeA[e] = c;
      edgeB[e] = nb;
      edgeLength[e] = angleBetween(corner, p, corner, q);
      edgeDistance[e] = angleBetween(center, 3 * c, center, 3 * nb);
      const mx = corner[p]! + corner[q]!;
      const my = corner[p + 1]! + corner[q + 1]!;
      const mz = corner[p + 2]! + corner[q + 2]!;
      const mr = Math.hypot(mx, my, mz);
      edgeMid[3 * e] = mx / mr;
      edgeMid[3 * e + 1] = my / mr;
      edgeMid[3 * e + 2] = mz / mr;
      const nx = corner[p + 1]! * corner[q + 2]! - corner[p + 2]! * corner[q + 1]!;
      const ny = corner[p + 2]! * corner[q]! - corner[p]! * corner[q + 2]!;
      const nz = corner[p]! * corner[q + 1]! - corner[p + 1]! * corner[q]!;
      const towardsB =
        nx * (center[3 * nb]! - center[3 * c]!) +
        ny * (center[3 * nb + 1]! - center[3 * c + 1]!) +
        nz * (center[3 * nb + 2]! - center[3 * c + 2]!);
      const scale = (towardsB >= 0 ? 1 : -1) / Math.hypot(nx, ny, nz);
      edgeNormal[3 * e] = nx * scale;
      edgeNormal[3 * e + 1] = ny * scale;
      edgeNormal[3 * e + 2] = nz * scale;
      cellEdge[4 * c + s] = e;
      cellEdgeSign[4 * c + s] = 1;
      const back = [0, 1, 2, 3].find((t) => cellNeighbor[4 * nb + t] === c);
      if (back === undefined) throw new Error(`cube-sphere grid ${n}: cell ${nb} does not border cell ${c}`);
      cellEdge[4 * nb + back] = e;
      cellEdgeSign[4 * nb + back] = -1;
    }
  }
  if (edges !== edgeCount) throw new Error(`cube-sphere grid ${n}: ${edges} edges, expected ${edgeCount}`);
  let minSpacing = Infinity;
  let spacingSum = 0;
  for (let e = 0; e < edgeCount; e++) {
    minSpacing = Math.min(minSpacing, edgeDistance[e]!);
    spacingSum += edgeDistance[e]!;
  }
  return {
    n,
    cellCount,
    center,
    area,
    edgeCount,
    edgeA,
    edgeB,
    edgeLength,
    edgeDistance,
    edgeNormal,
    edgeMid,
    cellEdge,
    cellEdgeSign,
    cellNeighbor,
    minSpacing,
    meanSpacing: spacingSum / edgeCount,
  };
}

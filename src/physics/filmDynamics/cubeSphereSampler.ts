import { type FacePoint, faceDirection, facePoint } from './cubeSphereFaces.ts';
import { type CubeSphereGrid, cellOf } from './cubeSphereGrid.ts';

/**
 * Bilinear sampling of a cell-centred field at any direction. Each face is padded with one ring of
 * ghost cells; a ghost's value is interpolated on the face its centre falls on (for an edge ghost
 * that point lies on a row of cell centres there, so the interpolation runs along the row only).
 * The 4 corner ghosts of a face, where three faces meet and no face continues the grid, are
 * extrapolated from their two edge ghosts and the corner cell (g₁ + g₂ − c, exact for a linear
 * field). The field's components (1 for η, 3 for a Cartesian velocity) need no change of basis across
 * face edges. On a GPU this is one halo pass per field and a 4-tap lookup per sample.
 * docs/flow.md#the-grid.
 */
export interface CubeSphereHalo {
  readonly grid: CubeSphereGrid;
  /** Padded index ((face·(n+2) + j+1)·(n+2) + i+1) → cell, or −1 for a ghost. */
  readonly paddedCell: Int32Array;
  /** For ghost g: padded index, then 4 cells and 4 weights. */
  readonly ghostPadded: Int32Array;
  readonly ghostCells: Int32Array;
  readonly ghostWeights: Float64Array;
  /** For each face corner: the padded corner ghost, its two edge ghosts and the corner cell's padded index. */
  readonly cornerGhosts: Int32Array;
}

const QUARTER_PI = Math.PI / 4;
const haloCache = new Map<number, CubeSphereHalo>();

/** The continuous cell coordinate (cell centres at integers) of gnomonic coordinate tan α on a face of n cells. */
const cellCoordinate = (n: number, tan: number): number => ((Math.atan(tan) + QUARTER_PI) * n) / (2 * QUARTER_PI) - 0.5;

export function cubeSphereHalo(grid: CubeSphereGrid): CubeSphereHalo {
  const cached = haloCache.get(grid.n);
  if (cached) return cached;
  const n = grid.n;
  const m = n + 2;
  const paddedCell = new Int32Array(6 * m * m).fill(-1);
  const ghosts: number[] = [];
  const cells: number[] = [];
  const weights: number[] = [];
  const corners: number[] = [];
  const dir = new Float64Array(3);
  const point: FacePoint = { face: 0, tanA: 0, tanB: 0 };
  const step = (2 * QUARTER_PI) / n;
  for (let f = 0; f < 6; f++) {
    for (let pj = 0; pj < m; pj++) {
      for (let pi = 0; pi < m; pi++) {
        const padded = (f * m + pj) * m + pi;
        const [i, j] = [pi - 1, pj - 1];
        const [insideI, insideJ] = [i >= 0 && i < n, j >= 0 && j < n];
        if (insideI && insideJ) {
          paddedCell[padded] = (f * n + j) * n + i;
          continue;
        }
        if (!insideI && !insideJ) {
          const [ei, ej] = [i < 0 ? 1 : n, j < 0 ? 1 : n];
          corners.push(padded, (f * m + pj) * m + ei, (f * m + ej) * m + pi, (f * m + ej) * m + ei);
          continue;
        }
        faceDirection(f, Math.tan(-QUARTER_PI + (i + 0.5) * step), Math.tan(-QUARTER_PI + (j + 0.5) * step), dir, 0);
        const p = facePoint(dir[0]!, dir[1]!, dir[2]!, point);
        const [ci, wi] = clampedLerp(n, cellCoordinate(n, p.tanA));
        const [cj, wj] = clampedLerp(n, cellCoordinate(n, p.tanB));
        const base = p.face * n * n;
        ghosts.push(padded);
        cells.push(base + cj * n + ci, base + cj * n + ci + 1, base + (cj + 1) * n + ci, base + (cj + 1) * n + ci + 1);
        weights.push((1 - wi) * (1 - wj), wi * (1 - wj), (1 - wi) * wj, wi * wj);
      }
    }
  }
  const halo = {
    grid,
    paddedCell,
    ghostPadded: Int32Array.from(ghosts),
    ghostCells: Int32Array.from(cells),
    ghostWeights: Float64Array.from(weights),
    cornerGhosts: Int32Array.from(corners),
  };
  haloCache.set(n, halo);
  return halo;
}

/** The lower of two neighbouring cells (kept inside the face) and the weight of the upper. */
function clampedLerp(n: number, coordinate: number): [number, number] {
  const lower = Math.min(n - 2, Math.max(0, Math.floor(coordinate)));
  return [lower, Math.min(1, Math.max(0, coordinate - lower))];
}

/** The padded copy of a field with `components` values per cell, ghosts filled (the halo pass). */
export function padField(halo: CubeSphereHalo, field: Float64Array, components: number, out?: Float64Array): Float64Array {
  const padded = out ?? new Float64Array(halo.paddedCell.length * components);
  const { paddedCell, ghostPadded, ghostCells, ghostWeights, cornerGhosts } = halo;
  for (let p = 0; p < paddedCell.length; p++) {
    const c = paddedCell[p]!;
    if (c >= 0) for (let k = 0; k < components; k++) padded[p * components + k] = field[c * components + k]!;
  }
  for (let g = 0; g < ghostPadded.length; g++) {
    const p = ghostPadded[g]!;
    for (let k = 0; k < components; k++) {
      let sum = 0;
      for (let t = 0; t < 4; t++) sum += ghostWeights[4 * g + t]! * field[ghostCells[4 * g + t]! * components + k]!;
      padded[p * components + k] = sum;
    }
  }
  for (let g = 0; g < cornerGhosts.length; g += 4) {
    const [p, a, b, c] = [cornerGhosts[g]!, cornerGhosts[g + 1]!, cornerGhosts[g + 2]!, cornerGhosts[g + 3]!];
    for (let k = 0; k < components; k++) {
      padded[p * components + k] = padded[a * components + k]! + padded[b * components + k]! - padded[c * components + k]!;
    }
  }
  return padded;
}

/**
 * A reusable sampler: `sample(x, y, z, out)` writes the bilinear value of a padded field (from
 * padField) at direction (x, y, z) into out[0..components−1].
 */
export function paddedSampler(halo: CubeSphereHalo, components: number) {
  const n = halo.grid.n;
  const m = n + 2;
  const point: FacePoint = { face: 0, tanA: 0, tanB: 0 };
  return (padded: Float64Array, x: number, y: number, z: number, out: Float64Array): void => {
    const p = facePoint(x, y, z, point);
    // Padded coordinates lie in [0.5, n + 0.5], so the four taps are always inside the padded face.
    const u = cellCoordinate(n, p.tanA) + 1;
    const v = cellCoordinate(n, p.tanB) + 1;
    const i = Math.min(n, Math.floor(u));
    const j = Math.min(n, Math.floor(v));
    const wu = u - i;
    const wv = v - j;
    const base = (p.face * m + j) * m + i;
    for (let k = 0; k < components; k++) {
      const a = padded[base * components + k]!;
      const b = padded[(base + 1) * components + k]!;
      const c = padded[(base + m) * components + k]!;
      const d = padded[(base + m + 1) * components + k]!;
      out[k] = (1 - wv) * ((1 - wu) * a + wu * b) + wv * ((1 - wu) * c + wu * d);
    }
  };
}

/** The nearest cell to a direction (for masks, which are not interpolated). */
export const nearestCell = (grid: CubeSphereGrid, x: number, y: number, z: number): number =>
  cellOf(grid.n, x, y, z, { face: 0, tanA: 0, tanB: 0 });

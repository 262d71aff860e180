/**
 * The cube-sphere mesh and its sampler, against geometry: the cells tile the sphere (areas sum to
 * 4π, each edge borders two cells that name each other), edge normals are unit tangents pointing
 * from A to B, and bilinear sampling reproduces constant fields exactly and linear ones to
 * second order in the spacing, across face edges and corners as well as inside faces.
 */
import { describe, expect, it } from 'vitest';
import { cubeSphereGrid } from '../../../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo, padField, paddedSampler } from '../../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { mulberry32 } from '../../../seededRandom.ts';
import { ALGEBRAIC_TOL } from '../../../tolerances.ts';

describe('cube-sphere grid', () => {
  for (const n of [4, 9, 16]) {
    const grid = cubeSphereGrid(n);
    it(`n = ${n}: ${6 * n * n} cells whose exact areas sum to 4π`, () => {
      expect(grid.cellCount).toBe(6 * n * n);
      expect(Math.abs(grid.area.reduce((s, a) => s + a, 0) - 4 * Math.PI)).toBeLessThan(ALGEBRAIC_TOL);
    });
    it(`n = ${n}: every edge borders two distinct cells, each listing it once with opposite signs`, () => {
      expect(grid.edgeCount).toBe(12 * n * n);
      const seen = new Int32Array(grid.edgeCount);
      for (let c = 0; c < grid.cellCount; c++) {
        for (let s = 0; s < 4; s++) {
          const e = grid.cellEdge[4 * c + s]!;
          const sign = grid.cellEdgeSign[4 * c + s]!;
          seen[e]! += 1;
          expect(sign === 1 ? grid.edgeA[e] : grid.edgeB[e]).toBe(c);
          expect(grid.cellNeighbor[4 * c + s]).toBe(sign === 1 ? grid.edgeB[e] : grid.edgeA[e]);
        }
      }
      expect(seen.every((count) => count === 2)).toBe(true);
    });
    it(`n = ${n}: edge normals are unit, tangent at the midpoint and point from A to B`, () => {
      const { edgeNormal: nv, edgeMid: m, center: c, edgeA, edgeB } = grid;
      for (let e = 0; e < grid.edgeCount; e++) {
        const [nx, ny, nz] = [nv[3 * e]!, nv[3 * e + 1]!, nv[3 * e + 2]!];
        expect(Math.abs(Math.hypot(nx, ny, nz) - 1)).toBeLessThan(ALGEBRAIC_TOL);
        expect(Math.abs(nx * m[3 * e]! + ny * m[3 * e + 1]! + nz * m[3 * e + 2]!)).toBeLessThan(ALGEBRAIC_TOL);
        const [a, b] = [3 * edgeA[e]!, 3 * edgeB[e]!];
        expect(nx * (c[b]! - c[a]!) + ny * (c[b + 1]! - c[a + 1]!) + nz * (c[b + 2]! - c[a + 2]!)).toBeGreaterThan(0);
      }
    });
  }
});

describe('cube-sphere sampler', () => {
  const random = mulberry32(11);
  const directions = Array.from({ length: 2000 }, () => {
    const z = 2 * random() - 1;
    const phi = 2 * Math.PI * random();
    return [Math.sqrt(1 - z * z) * Math.cos(phi), Math.sqrt(1 - z * z) * Math.sin(phi), z] as const;
  });
  /** The largest error sampling f(x) = 0.3 + 0.5x − 0.2y + 0.7z, known at the cell centres. */
  const linearError = (n: number): number => {
    const grid = cubeSphereGrid(n);
    const halo = cubeSphereHalo(grid);
    const f = (x: number, y: number, z: number) => 0.3 + 0.5 * x - 0.2 * y + 0.7 * z;
    const field = new Float64Array(grid.cellCount).map((_, c) => f(grid.center[3 * c]!, grid.center[3 * c + 1]!, grid.center[3 * c + 2]!));
    const padded = padField(halo, field, 1);
    const sample = paddedSampler(halo, 1);
    const out = new Float64Array(1);
    return Math.max(...directions.map(([x, y, z]) => (sample(padded, x, y, z, out), Math.abs(out[0]! - f(x, y, z)))));
  };
  it('reproduces a constant exactly everywhere, face edges and corners included', () => {
    const grid = cubeSphereGrid(8);
    const halo = cubeSphereHalo(grid);
    const padded = padField(halo, new Float64Array(grid.cellCount).fill(2.5), 1);
    const sample = paddedSampler(halo, 1);
    const out = new Float64Array(1);
    for (const [x, y, z] of directions) {
      sample(padded, x, y, z, out);
      expect(Math.abs(out[0]! - 2.5)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });
  it('samples a smooth field with an error falling as the square of the spacing', () => {
    const [coarse, fine] = [linearError(8), linearError(32)];
    // Halving the spacing twice divides a second-order error by ~16; allow 8 for the sampling's luck.
    expect(fine).toBeLessThan(coarse / 8);
    expect(fine).toBeLessThan(2e-3);
  });
});

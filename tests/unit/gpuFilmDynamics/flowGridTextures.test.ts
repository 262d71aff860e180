/** The GPU's view of the cube-sphere: the atlases hold every cell, padded cell and edge once, and the halo's taps reproduce the twin's ghosts. */
import { describe, expect, it } from 'vitest';
import { cubeSphereGrid } from '../../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo, padField } from '../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { cellTexelIndex, edgeAtlasSize, faceAtlasSize, paddedTexelIndex } from '../../../src/gpuFilmDynamics/flowAtlas.ts';
import { HALO_TAP_TEXELS, flowGridTextures } from '../../../src/gpuFilmDynamics/flowGridTextures.ts';
import { HALO_TAPS } from '../../../src/gpuFilmDynamics/flowTexels.ts';
import { mulberry32 } from '../../seededRandom.ts';
import { HALO_WEIGHT_SUM_TOL } from '../../tolerances.ts';

const N = 5;

describe('flow atlases', () => {
  it('the cell and padded atlases hold each cell once, every texel used; the edge atlas holds 12N² edges exactly', () => {
    for (const [count, index, side] of [
      [6 * N * N, (c: number) => cellTexelIndex(N, c), N],
      [6 * (N + 2) ** 2, (p: number) => paddedTexelIndex(N, p), N + 2],
    ] as const) {
      const { width, height } = faceAtlasSize(side);
      const texels = new Set(Array.from({ length: count }, (_, c) => index(c)));
      expect(texels.size).toBe(count);
      expect(width * height).toBe(count);
      expect(Math.min(...texels)).toBe(0);
    }
    const edges = edgeAtlasSize(N);
    expect(edges.width * edges.height).toBe(cubeSphereGrid(N).edgeCount);
  });

  it("the halo's taps give every padded value of the twin's padField (corner ghosts included)", () => {
    const grid = cubeSphereGrid(N);
    const halo = cubeSphereHalo(grid);
    const random = mulberry32(3);
    const field = Float64Array.from({ length: grid.cellCount }, () => random());
    const padded = padField(halo, field, 1);
    const taps = flowGridTextures(grid, halo).uHaloTaps.image.data as Float32Array;
    let worst = 0;
    /** Field `name` of the HALO_TAPS record in texel `texel` of the table. */
    const tap = (texel: number, name: keyof typeof HALO_TAPS.fields) => taps[texel * HALO_TAPS.floats + HALO_TAPS.offsets[name]]!;
    for (let p = 0; p < padded.length; p++) {
      let sum = 0;
      let weights = 0;
      for (let k = 0; k < HALO_TAP_TEXELS; k++) {
        const texel = HALO_TAP_TEXELS * paddedTexelIndex(N, p) + k;
        for (const [cell, weight] of [
          ['CELL_0', 'WEIGHT_0'],
          ['CELL_1', 'WEIGHT_1'],
        ] as const) {
          sum += tap(texel, weight) * field[tap(texel, cell)]!;
          weights += tap(texel, weight);
        }
      }
      worst = Math.max(worst, Math.abs(sum - padded[p]!));
      // A ghost is an interpolation (or g₁ + g₂ − c): its weights sum to 1.
      expect(Math.abs(weights - 1)).toBeLessThan(HALO_WEIGHT_SUM_TOL);
    }
    // float32 weights: rounding of 1e-7 per tap.
    expect(worst).toBeLessThan(1e-6);
  });
});

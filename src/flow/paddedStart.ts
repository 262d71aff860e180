import type { DataTexture } from 'three';
import type { CubeSphereGrid } from '../physics/flow/cubeSphereGrid.ts';
import { cubeSphereHalo, padField } from '../physics/flow/cubeSphereSampler.ts';
import type { initialFilm } from '../physics/flow/initialFilm.ts';
import { floatTexture } from '../gpu/floatRow.ts';
import { faceAtlasSize, paddedTexelIndex } from './flowAtlas.ts';

/**
 * The film at its start (`start`, initialFilm's on `grid`: η, Γ, intact, 0) padded on the CPU, in
 * the padded atlas the bubble samples: the twin of the simulation's start and halo passes
 * (padField), to draw before any of the simulation's programs is compiled.
 */
export function paddedStartTexture(grid: CubeSphereGrid, start: ReturnType<typeof initialFilm>): DataTexture {
  const { eta, gamma } = start;
  const film = new Float64Array(4 * grid.cellCount);
  for (let c = 0; c < grid.cellCount; c++) film.set([eta[c]!, gamma[c]!, 1, 0], 4 * c);
  const padded = padField(cubeSphereHalo(grid), film, 4);
  const size = faceAtlasSize(grid.n + 2);
  const data = new Float32Array(4 * size.width * size.height);
  for (let p = 0; p < padded.length / 4; p++) data.set(padded.subarray(4 * p, 4 * p + 4), 4 * paddedTexelIndex(grid.n, p));
  return floatTexture(data, size.width, size.height);
}

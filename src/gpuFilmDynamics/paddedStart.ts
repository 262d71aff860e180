import type { DataTexture } from 'three';
import type { CubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo, padField } from '../physics/filmDynamics/cubeSphereSampler.ts';
import type { initialFilm } from '../physics/filmDynamics/initialFilm.ts';
import { floatTexture } from '../gpu/floatRow.ts';
import { packTexelRecord } from '../gpu/texelRecord.ts';
import { faceAtlasSize, paddedTexelIndex } from './flowAtlas.ts';
import { FLOW_FILM } from './flowTexels.ts';

/** The film at its start (`start`, initialFilm's on `grid`) as FLOW_FILM records in the twin's cell order: its η and Γ, every cell intact, none marked. */
export function startFilmRecords(grid: CubeSphereGrid, start: ReturnType<typeof initialFilm>): Float64Array {
  const film = new Float64Array(FLOW_FILM.floats * grid.cellCount);
  for (let c = 0; c < grid.cellCount; c++)
    packTexelRecord(FLOW_FILM, film, c, { ETA: start.eta[c]!, GAMMA: start.gamma[c]!, INTACT: 1, MARK: 0 });
  return film;
}

/**
 * The film at its start padded on the CPU, in the padded atlas the bubble samples: the twin of the
 * simulation's start and halo passes (padField of startFilmRecords), to draw before any of the
 * simulation's programs is compiled.
 */
export function paddedStartTexture(grid: CubeSphereGrid, start: ReturnType<typeof initialFilm>): DataTexture {
  const texel = FLOW_FILM.floats;
  const padded = padField(cubeSphereHalo(grid), startFilmRecords(grid, start), texel);
  const size = faceAtlasSize(grid.n + 2);
  const data = new Float32Array(texel * size.width * size.height);
  for (let p = 0; p < padded.length / texel; p++)
    data.set(padded.subarray(texel * p, texel * p + texel), texel * paddedTexelIndex(grid.n, p));
  return floatTexture(data, size.width, size.height);
}

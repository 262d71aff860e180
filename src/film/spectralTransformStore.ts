import { WorkerTexels } from '../threads/workerTexels.ts';
import { type SpectralLight, lightWeights } from '../physics/spectralWeights.ts';
import { spectralTransformTexels } from './spectralTransformTexels.ts';

/**
 * The texels of the last three lights computed (0.85 MB each: a film's three colour planes), on
 * this thread or in the worker (spectralTransformWorker.ts): the table pass lets go of its textures
 * after each build, and the next build for the same light (an index changed) then uploads them
 * again instead of computing them again.
 */
const store = new WorkerTexels(
  () => new Worker(new URL('./spectralTransformWorker.ts', import.meta.url), { type: 'module' }),
  (key) => {
    return lightWeights(JSON.parse(key) as SpectralLight);
  },
  spectralTransformTexels,
  3,
);

/** The texels of the light with this key (spectralLightKey), computed on this thread unless at hand. */
export const spectralTransformTexelsOf = (key: string): Float32Array => store.of(key);

/**
 * Whether the texels of the light with this key are at hand. If not, the worker is asked for them
 * (once) and the answer is false until they arrive; where there is no worker they are computed on
 * this thread at once (true).
 */
export const spectralTransformTexelsReady = (key: string): boolean => store.ready(key);

/** A promise kept once the texels of the light with this key are at hand (asked of the worker, or computed here where there is none). */
export const spectralTransformTexelsWhenReady = (key: string): Promise<void> => store.whenReady(key);

import { WorkerRequests } from '../threads/workerRequests.ts';
import { type SpectralLight, spectralTransformTexels } from './spectralTransformTexels.ts';
import type { SpectralTransformReply, SpectralTransformRequest } from './spectralTransformWorker.ts';

/**
 * The texels of the last light computed (0.85 MB), on this thread or in the worker: the table
 * pass lets go of its texture after each build, and the next build for the same light (an index
 * changed) then uploads them again instead of computing them again.
 */
let last: { readonly key: string; readonly data: Float32Array } | null = null;
const requests = new WorkerRequests<SpectralTransformReply>(
  () => new Worker(new URL('./spectralTransformWorker.ts', import.meta.url), { type: 'module' }),
  (reply) => (last = { key: reply.key, data: reply.texels }),
  // The lights asked of a worker that failed are computed on this thread when next asked for.
);

/** The texels of the light with this key (spectralLightKey), computed on this thread unless at hand. */
export function spectralTransformTexelsOf(key: string): Float32Array {
  if (last?.key === key) return last.data;
  const data = spectralTransformTexels(JSON.parse(key) as SpectralLight);
  last = { key, data };
  return data;
}

/**
 * Whether the texels of the light with this key are at hand. If not, the worker is asked for them
 * (once) and the answer is false until they arrive; where there is no worker they are computed on
 * this thread at once (true).
 */
export function spectralTransformTexelsReady(key: string): boolean {
  if (last?.key === key) return true;
  if (requests.ask(key, { key } satisfies SpectralTransformRequest)) return false;
  spectralTransformTexelsOf(key);
  return true;
}

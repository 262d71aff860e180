import { type SpectralLight, spectralTransformTexels } from './spectralTransformTexels.ts';
import type { SpectralTransformReply, SpectralTransformRequest } from './spectralTransformWorker.ts';

/**
 * The texels of the last light computed (0.85 MB), on this thread or in the worker: the table
 * pass lets go of its texture after each build, and the next build for the same light (an index
 * changed) then uploads them again instead of computing them again.
 */
let last: { readonly key: string; readonly data: Float32Array } | null = null;
/** The worker, made when first needed; null where there are no Workers (Node) or it failed. */
let worker: Worker | null | undefined;
/** The lights the worker is computing, by key. */
const computing = new Set<string>();

function theWorker(): Worker | null {
  if (worker !== undefined) return worker;
  worker = null;
  if (typeof Worker === 'undefined') return null;
  try {
    const w = new Worker(new URL('./spectralTransformWorker.ts', import.meta.url), { type: 'module' });
    w.addEventListener('message', (e: MessageEvent<SpectralTransformReply>) => {
      computing.delete(e.data.key);
      last = { key: e.data.key, data: e.data.texels };
    });
    // A worker that cannot load or run (its file not served beside the module, a page's CSP):
    // the lights asked of it are computed on this thread when next asked for.
    const fail = () => {
      w.terminate();
      worker = null;
      computing.clear();
    };
    w.addEventListener('error', fail);
    w.addEventListener('messageerror', fail);
    worker = w;
  } catch {
    // The constructor refused (a SecurityError): no worker.
  }
  return worker;
}

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
  const w = theWorker();
  if (!w) {
    spectralTransformTexelsOf(key);
    return true;
  }
  if (!computing.has(key)) {
    computing.add(key);
    w.postMessage({ key } satisfies SpectralTransformRequest);
  }
  return false;
}

import { WorkerTexels } from '../threads/workerTexels.ts';
import { dispersiveRowsOfKey } from './dispersiveRows.ts';

/**
 * The row terms of the last few dispersive tables (a coarse and a full grid of this film and the
 * one before: up to 1.2 MB each), computed in a Web Worker (dispersiveRowsWorker.ts): 0.1–0.3 s
 * of float64 work per grid that the app's frames then do not wait for.
 */
const store = new WorkerTexels(
  () => new Worker(new URL('./dispersiveRowsWorker.ts', import.meta.url), { type: 'module' }),
  (key) => key,
  dispersiveRowsOfKey,
  4,
);

/** The row terms for this key (dispersiveRowsKey), computed on this thread unless at hand. */
export const dispersiveRowsOf = (key: string): Float32Array => store.of(key);

/** Whether they are at hand; if not, the worker is asked for them (false until they arrive). Without a worker, computed here (true). */
export const dispersiveRowsReady = (key: string): boolean => store.ready(key);

/** A promise kept once they are at hand (asked of the worker, or computed here where there is none). */
export const dispersiveRowsWhenReady = (key: string): Promise<void> => store.whenReady(key);

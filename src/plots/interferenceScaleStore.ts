import { WorkerRequests } from '../threads/workerRequests.ts';
import { type ScaleColor, type ScaleRequest, interferenceScaleOf } from './interferenceScale.ts';
import type { ScaleReply } from './interferenceScaleWorker.ts';

/** Who waits for each scale being computed, and what it is. */
const waiting = new Map<string, { readonly request: ScaleRequest; readonly callbacks: ((colors: ScaleColor[]) => void)[] }>();

function settle(key: string, colors: ScaleColor[]): void {
  const w = waiting.get(key);
  waiting.delete(key);
  w?.callbacks.forEach((callback) => callback(colors));
}

const requests = new WorkerRequests<ScaleReply>(
  () => new Worker(new URL('./interferenceScaleWorker.ts', import.meta.url), { type: 'module' }),
  (reply) => settle(reply.key, reply.colors),
  // The scales pending in a worker that failed are computed here, and their callers called.
  (keys) => keys.forEach((key) => settle(key, interferenceScaleOf(waiting.get(key)!.request))),
);

/**
 * The interference colour scale for `request`, computed off the main thread (the float64
 * reference over 160 films is up to a second for a dispersive film): null while its worker
 * computes it, then `onReady` is called with it. Where there is no worker it is computed at once
 * and returned.
 */
export function interferenceScaleFor(request: ScaleRequest, onReady: (colors: ScaleColor[]) => void): ScaleColor[] | null {
  const key = JSON.stringify(request);
  const w = waiting.get(key) ?? { request, callbacks: [] };
  waiting.set(key, w);
  if (!requests.ask(key, () => ({ ...request, key }))) {
    waiting.delete(key);
    return interferenceScaleOf(request);
  }
  w.callbacks.push(onReady);
  return null;
}

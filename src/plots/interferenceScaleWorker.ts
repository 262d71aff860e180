/**
 * The Web Worker that computes interference colour scales off the main thread
 * (interferenceScaleStore.ts starts it): a ScaleRequest is answered with its key and colours.
 */
import { type ScaleRequest, interferenceScaleOf } from './interferenceScale.ts';

export interface ScaleReply {
  readonly key: string;
  readonly colors: ReturnType<typeof interferenceScaleOf>;
}

addEventListener('message', (e: MessageEvent<ScaleRequest & { readonly key: string }>) => {
  postMessage({ key: e.data.key, colors: interferenceScaleOf(e.data) } satisfies ScaleReply);
});

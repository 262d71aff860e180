/**
 * The Web Worker that computes lights' spectral transforms off the main thread
 * (spectralTransformStore.ts starts it): a message { key } (spectralLightKey) is answered with
 * { key, texels }, the texels transferred, not copied.
 */
import { type SpectralLight, spectralTransformTexels } from './spectralTransformTexels.ts';

export interface SpectralTransformRequest {
  readonly key: string;
}

export interface SpectralTransformReply {
  readonly key: string;
  readonly texels: Float32Array;
}

addEventListener('message', (e: MessageEvent<SpectralTransformRequest>) => {
  const { key } = e.data;
  const texels = spectralTransformTexels(JSON.parse(key) as SpectralLight);
  postMessage({ key, texels } satisfies SpectralTransformReply, { transfer: [texels.buffer] });
});

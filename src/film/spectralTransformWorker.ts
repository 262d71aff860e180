/**
 * The Web Worker that computes lights' spectral transforms off the main thread
 * (spectralTransformStore.ts starts it): a message { key } (spectralLightKey) is answered with
 * { key, texels }, the texels transferred, not copied.
 */
import { serveTexels } from '../threads/workerTexels.ts';
import { type SpectralLight, spectralTransformTexels } from './spectralTransformTexels.ts';

serveTexels((key) => spectralTransformTexels(JSON.parse(key) as SpectralLight));

/**
 * The Web Worker that computes lights' spectral transforms off the main thread
 * (spectralTransformStore.ts starts it): a message { key, input } (spectralLightKey, the light's
 * weights) is answered with { key, texels }, the texels transferred, not copied. It is given the
 * weights, not the light, so it carries no light's data.
 */
import { serveTexels } from '../threads/workerTexels.ts';
import { spectralTransformTexels } from './spectralTransformTexels.ts';

serveTexels(spectralTransformTexels);

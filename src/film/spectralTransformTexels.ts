import type { SpectralLight, SpectralWeights } from '../physics/spectralWeights.ts';
import { SPECTRAL_TRANSFORM_COUNT, spectralTransform } from '../physics/spectralTransform.ts';

/** Entries per texture row (WebGL2 guarantees 2048; 4096 is common, SwiftShader has 8192). */
export const SPECTRAL_TRANSFORM_WIDTH = 2048;
export const SPECTRAL_TRANSFORM_ROWS = Math.ceil(SPECTRAL_TRANSFORM_COUNT / SPECTRAL_TRANSFORM_WIDTH);

/** The light's key: lights with the same key have the same weights (settings holding a light give its own fields only). */
export const spectralLightKey = (light: SpectralLight): string =>
  JSON.stringify({ illuminant: light.illuminant, normalization: light.normalization, lightTint: light.lightTint, basis: light.basis });

/**
 * The spectral transform (src/physics/spectralTransform.ts, an FFT) of a light's weights
 * (spectralWeights of its illuminant, normalisation and tint) as the RGBA float
 * texels of a SPECTRAL_TRANSFORM_WIDTH × 2 SPECTRAL_TRANSFORM_ROWS texture: rows 0 .. ROWS-1 hold
 * Re H (x, y, z), rows ROWS .. 2 ROWS-1 Im H, entry i at (i mod WIDTH, i div WIDTH). No DOM, no
 * three.js: the main thread and the worker (spectralTransformWorker.ts) compute it alike.
 */
export function spectralTransformTexels(weights: SpectralWeights): Float32Array {
  const { values, count } = spectralTransform(weights);
  const imaginary = 4 * SPECTRAL_TRANSFORM_WIDTH * SPECTRAL_TRANSFORM_ROWS;
  const data = new Float32Array(2 * imaginary);
  for (let i = 0; i < count; i++) {
    data.set([values[6 * i]!, values[6 * i + 1]!, values[6 * i + 2]!, 0], 4 * i);
    data.set([values[6 * i + 3]!, values[6 * i + 4]!, values[6 * i + 5]!, 0], imaginary + 4 * i);
  }
  return data;
}

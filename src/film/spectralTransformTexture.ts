import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { type Normalization, spectralWeights } from '../physics/spectralWeights.ts';
import {
  SPECTRAL_TRANSFORM_CARRIER_PER_NM,
  SPECTRAL_TRANSFORM_COUNT,
  SPECTRAL_TRANSFORM_STEP_NM,
  spectralTransform,
} from '../physics/spectralTransform.ts';
import { AIRY_SERIES_MAX_ORDERS, AIRY_SERIES_TOLERANCE } from '../physics/airySeries.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';

/** Entries per texture row (WebGL2 guarantees 2048; 4096 is common, SwiftShader has 8192). */
const WIDTH = 2048;
const ROWS = Math.ceil(SPECTRAL_TRANSFORM_COUNT / WIDTH);

/**
 * The texels of the last light asked for (0.85 MB): the table pass lets go of its texture after
 * each build, and the next build for the same light (an index changed) then uploads them again
 * instead of computing them again.
 */
let last: { readonly key: string; readonly data: Float32Array } | null = null;

function texels(key: string): Float32Array {
  if (last?.key === key) return last.data;
  const { illuminant, normalization } = JSON.parse(key) as { illuminant: IlluminantSpec; normalization: Normalization };
  const { values, count } = spectralTransform(spectralWeights(illuminant, normalization));
  // Rows 0 .. ROWS-1: Re H (x, y, z); rows ROWS .. 2 ROWS-1: Im H, entry i at (i mod WIDTH, i div WIDTH).
  const data = new Float32Array(4 * WIDTH * 2 * ROWS);
  for (let i = 0; i < count; i++) {
    data.set([values[6 * i]!, values[6 * i + 1]!, values[6 * i + 2]!, 0], 4 * i);
    data.set([values[6 * i + 3]!, values[6 * i + 4]!, values[6 * i + 5]!, 0], 4 * (i + WIDTH * ROWS));
  }
  last = { key, data };
  return data;
}

const shared = new SharedTextures((key) => {
  const data = texels(key);
  const texture = new DataTexture(data, WIDTH, 2 * ROWS, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
});

/**
 * The light's spectral transform (src/physics/spectralTransform.ts) as a float texture read by
 * shaders/physics/airySeries.glsl, for `holder`; computed on the CPU when a light is first asked for
 * (~30 ms) and shared by the holders of the same light (SharedTextures).
 */
export const spectralTransformTexture = (illuminant: IlluminantSpec, normalization: Normalization, holder: object): DataTexture =>
  shared.hold(JSON.stringify({ illuminant, normalization }), holder);

export const releaseSpectralTransformTexture = (holder: object): void => shared.release(holder);

/** The defines shaders/physics/airySeries.glsl reads; `maxOrders` below the default truncates the series (the peers' m ≤ 2, 3). */
export const airySeriesDefines = (maxOrders = AIRY_SERIES_MAX_ORDERS): Record<string, number> => ({
  TFC_SPECTRAL_TRANSFORM_WIDTH: WIDTH,
  TFC_SPECTRAL_TRANSFORM_ROWS: ROWS,
  TFC_SPECTRAL_TRANSFORM_COUNT: SPECTRAL_TRANSFORM_COUNT,
  TFC_SPECTRAL_TRANSFORM_STEP_NM: SPECTRAL_TRANSFORM_STEP_NM,
  TFC_SPECTRAL_TRANSFORM_CARRIER_PER_NM: SPECTRAL_TRANSFORM_CARRIER_PER_NM,
  TFC_AIRY_SERIES_MAX_ORDERS: maxOrders,
  TFC_AIRY_SERIES_TOLERANCE: AIRY_SERIES_TOLERANCE,
  // A peer's truncation is the series cut short, with no fallback to bins where it needs more terms.
  TFC_AIRY_SERIES_TRUNCATED: maxOrders < AIRY_SERIES_MAX_ORDERS ? 1 : 0,
});

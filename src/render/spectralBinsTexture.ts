import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { type Normalization, significantBins, spectralBins, spectralWeights } from '../physics/spectralIntegration.ts';

const cache = new Map<string, DataTexture>();
const definesCache = new Map<string, Record<string, number>>();

/**
 * The bin weights ∫_bin I_in x̄, ȳ, z̄ dλ / k as a `count` × 1 float texture, from the reference
 * (one source of truth). Shared by every material that needs the same weights.
 */
export function spectralBinsTexture(illuminant: IlluminantSpec, normalization: Normalization, count: number): DataTexture {
  const key = `${JSON.stringify(illuminant)}|${normalization}|${count}`;
  const hit = cache.get(key);
  if (hit) return hit;
  const { weights } = spectralBins(spectralWeights(illuminant, normalization), count);
  const data = new Float32Array(4 * count);
  for (let b = 0; b < count; b++) data.set([weights[3 * b]!, weights[3 * b + 1]!, weights[3 * b + 2]!, 1], 4 * b);
  const texture = new DataTexture(data, count, 1, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  cache.set(key, texture);
  return texture;
}

/**
 * The defines of shaders/spectralIntegration.glsl: `count` bins, of which the loop visits only
 * those that matter under this illuminant (`significantBins` with `tailTolerance`).
 */
export function spectralBinDefines(
  illuminant: IlluminantSpec,
  normalization: Normalization,
  count: number,
  tailTolerance: number,
): Record<string, number> {
  const key = `${JSON.stringify(illuminant)}|${normalization}|${count}|${tailTolerance}`;
  const hit = definesCache.get(key);
  if (hit) return hit;
  const { first, end } = significantBins(spectralBins(spectralWeights(illuminant, normalization), count), tailTolerance);
  const defines = { SPECTRAL_BINS: count, SPECTRAL_BIN_FIRST: first, SPECTRAL_BIN_END: end };
  definesCache.set(key, defines);
  return defines;
}

/** Frees the shared textures (after a lost context, or when the last bubble goes). */
export function disposeSpectralBinsTextures(): void {
  for (const t of cache.values()) t.dispose();
  cache.clear();
}

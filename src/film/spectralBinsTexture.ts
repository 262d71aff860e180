import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import { significantBins, spectralBins } from '../physics/binnedIntegration.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM, type Normalization, spectralWeights } from '../physics/spectralWeights.ts';

const shared = new SharedTextures((key) => {
  const { illuminant, normalization, count } = JSON.parse(key) as {
    illuminant: IlluminantSpec;
    normalization: Normalization;
    count: number;
  };
  const { weights } = spectralBins(spectralWeights(illuminant, normalization), count);
  const data = new Float32Array(4 * count);
  for (let b = 0; b < count; b++) data.set([weights[3 * b]!, weights[3 * b + 1]!, weights[3 * b + 2]!, 1], 4 * b);
  const texture = new DataTexture(data, count, 1, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
});

/**
 * The bin weights ∫_bin I_in x̄, ȳ, z̄ dλ / k as a `count` × 1 float texture, from the reference
 * (one source of truth), for `holder`; shared by the holders of the same weights (SharedTextures).
 */
export const spectralBinsTexture = (illuminant: IlluminantSpec, normalization: Normalization, count: number, holder: object): DataTexture =>
  shared.hold(JSON.stringify({ illuminant, normalization, count }), holder);

/** The uniform shaders/physics/binnedIntegration.glsl declares for the bin weights. */
export const spectralBinsUniforms = () => ({ uSpectralBins: { value: null as DataTexture | null } });

/** `holder` needs no spectral bins texture any more. */
export const releaseSpectralBinsTexture = (holder: object): void => shared.release(holder);

/** Illuminants spanning the ones offered: flat, and daylight at both ends of its CCT range. */
const SPAN: readonly IlluminantSpec[] = ['E', { daylightCct: 4000 }, { daylightCct: 25000 }, 'D65-table'];
const definesCache = new Map<string, Record<string, number>>();

/**
 * The defines of shaders/physics/binnedIntegration.glsl: `count` bins, of which the loop visits only
 * those where the colour-matching functions matter (`significantBins` with `tailTolerance`) under
 * any offered illuminant — so the defines, and the compiled program, do not depend on the light,
 * and bubbles under D55 and D93 share one program.
 */
export function spectralBinDefines(count: number, tailTolerance: number): Record<string, number> {
  const key = `${count}|${tailTolerance}`;
  const hit = definesCache.get(key);
  if (hit) return hit;
  const ranges = SPAN.map((i) => significantBins(spectralBins(spectralWeights(i, 'white'), count), tailTolerance));
  const defines = {
    TFC_SPECTRAL_BINS: count,
    // The integration's range, as the TypeScript reference holds it.
    TFC_LAMBDA_MIN_NM: LAMBDA_MIN_NM,
    TFC_LAMBDA_MAX_NM: LAMBDA_MAX_NM,
    TFC_SPECTRAL_BIN_FIRST: Math.min(...ranges.map((r) => r.first)),
    TFC_SPECTRAL_BIN_END: Math.max(...ranges.map((r) => r.end)),
  };
  definesCache.set(key, defines);
  return defines;
}

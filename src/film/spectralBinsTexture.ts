import { DataTexture, FloatType, NearestFilter, RGBAFormat, type ShaderMaterial, Vector4 } from 'three';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { MAX_LIGHT_LINES } from '../physics/lightLines.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import { significantBins, spectralBins } from '../physics/binnedIntegration.ts';
import { lightBins } from '../physics/environmentMatrix.ts';
import {
  LAMBDA_MAX_NM,
  LAMBDA_MIN_NM,
  type SpectralLight,
  lightWeights,
  planeLights,
  planesLight,
  spectralWeights,
  type PlaneCount,
} from '../physics/spectralWeights.ts';
import { spectralLightKey } from './spectralTransformTexels.ts';

/** The texture row of plane p's weights: row 1 holds the windows, which every plane shares (lightBins). */
export const weightsRow = (p: number) => (p === 0 ? 0 : p + 1);

const shared = new SharedTextures((key) => {
  const { light, count, planes } = JSON.parse(key) as { light: SpectralLight; count: number; planes: PlaneCount };
  const bins = planeLights(light, planes).map((l) => lightBins(l, count));
  const rows = planes === 1 ? 2 : 4;
  const data = new Float32Array(4 * count * rows);
  bins.forEach(({ weights }, p) => {
    for (let b = 0; b < count; b++)
      data.set([weights[3 * b]!, weights[3 * b + 1]!, weights[3 * b + 2]!, 1], 4 * (weightsRow(p) * count + b));
  });
  const { windows } = bins[0]!;
  for (let b = 0; b < count; b++) data.set([windows[2 * b]!, windows[2 * b + 1]!, 0, 0], 4 * (count + b));
  const texture = new DataTexture(data, count, rows, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
});

/**
 * The bin weights ∫_bin I_in T x̄, ȳ, z̄ dλ / k (T the tint's spectrum) and each bin's window
 * (SpectralBins.windows) as a `count` × 2 float texture, from the reference (one source of truth),
 * for `holder`; shared by the holders of the same weights (SharedTextures). With `planes` 3 (a
 * film's environment matrix, shaders/physics/binnedIntegration.glsl's TFC_ENVIRONMENT_MATRIX) it is
 * `count` × 4: row 0 the weights of the light times the red basis spectrum, row 1 the windows,
 * rows 2 and 3 green's and blue's.
 */
export const spectralBinsTexture = (light: SpectralLight, count: number, holder: object, planes: PlaneCount = 1): DataTexture =>
  shared.hold(`{"light":${spectralLightKey(planesLight(light, planes))},"count":${count},"planes":${planes}}`, holder);

/** The uniforms shaders/physics/binnedIntegration.glsl declares for the bin weights and a line source's lines. */
export const spectralBinsUniforms = () => ({
  uSpectralBins: { value: null as DataTexture | null },
  uLightLines: { value: Array.from({ length: 3 * MAX_LIGHT_LINES }, () => new Vector4()) },
  uLightLineCount: { value: 0 },
});

/**
 * Points `u` (spectralBinsUniforms) at the light's bin weights, held for `holder`, and at its lines
 * (none for a light with a spectrum): each line's weights p T(λ) x̄, ȳ, z̄(λ)/k and λ, from the
 * reference; with `planes` 3, plane p's line i at p · TFC_LIGHT_LINES_MAX + i.
 */
export function bindSpectralBins(
  u: ShaderMaterial['uniforms'],
  light: SpectralLight,
  count: number,
  holder: object,
  planes: PlaneCount = 1,
): void {
  u.uSpectralBins!.value = spectralBinsTexture(light, count, holder, planes);
  planeLights(light, planes).forEach((pl, p) => {
    const lines = lightWeights(pl).lines ?? [];
    lines.forEach((l, i) => (u.uLightLines!.value as Vector4[])[p * MAX_LIGHT_LINES + i]!.set(l.x, l.y, l.z, l.nm));
    u.uLightLineCount!.value = lines.length;
  });
}

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
    TFC_LIGHT_LINES_MAX: MAX_LIGHT_LINES,
  };
  definesCache.set(key, defines);
  return defines;
}

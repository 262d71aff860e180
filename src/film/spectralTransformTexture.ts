import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { SPECTRAL_TRANSFORM_CARRIER_PER_NM, SPECTRAL_TRANSFORM_COUNT, SPECTRAL_TRANSFORM_STEP_NM } from '../physics/spectralTransform.ts';
import { AIRY_SERIES_MAX_ORDERS, AIRY_SERIES_TOLERANCE } from '../physics/airySeries.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import { SPECTRAL_TRANSFORM_ROWS as ROWS, SPECTRAL_TRANSFORM_WIDTH as WIDTH, spectralLightKey } from './spectralTransformTexels.ts';
import { type SpectralLight, planeLights, type PlaneCount } from '../physics/spectralWeights.ts';
import { spectralTransformTexelsOf, spectralTransformTexelsReady, spectralTransformTexelsWhenReady } from './spectralTransformStore.ts';

/** The key of a light's transform in `planes` colour planes: its plane lights' keys, one per line. */
const planesKey = (light: SpectralLight, planes: PlaneCount): string => planeLights(light, planes).map(spectralLightKey).join('\n');

const shared = new SharedTextures((key) => {
  const planes = key.split('\n').map(spectralTransformTexelsOf);
  const data = new Float32Array(planes.reduce((n, p) => n + p.length, 0));
  planes.reduce((offset, p) => (data.set(p, offset), offset + p.length), 0);
  const texture = new DataTexture(data, WIDTH, 2 * ROWS * planes.length, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
});

/**
 * The light's spectral transform (src/physics/spectralTransform.ts) as a float texture read by
 * shaders/physics/airySeries.glsl, for `holder`; computed on this thread if not at hand (~30 ms a
 * plane; see spectralTransformReady) and shared by the holders of the same light (SharedTextures).
 * In three colour planes (a film's environment matrix) the transforms of the light times each basis
 * spectrum, one above the other.
 */
export const spectralTransformTexture = (light: SpectralLight, holder: object, planes: PlaneCount = 1): DataTexture =>
  shared.hold(planesKey(light, planes), holder);

/**
 * Whether `spectralTransformTexture` for the light would return at once (a texture held, or its
 * texels at hand); if not, they are being computed in a Web Worker (spectralTransformStore.ts).
 */
export function spectralTransformReady(light: SpectralLight, planes: PlaneCount = 1): boolean {
  const key = planesKey(light, planes);
  // Each plane asked of the worker at once: not one after another.
  return shared.has(key) || key.split('\n').map(spectralTransformTexelsReady).every(Boolean);
}

/** A promise kept once `spectralTransformTexture` for the light would return at once: its texels computed in the Web Worker, or here where there is none. */
export async function spectralTransformWhenReady(light: SpectralLight, planes: PlaneCount = 1): Promise<void> {
  const key = planesKey(light, planes);
  if (!shared.has(key)) await Promise.all(key.split('\n').map(spectralTransformTexelsWhenReady));
}

export const releaseSpectralTransformTexture = (holder: object): void => shared.release(holder);

/** The uniform shaders/physics/airySeries.glsl declares for the spectral transform. */
export const spectralTransformUniforms = () => ({ uSpectralTransform: { value: null as DataTexture | null } });

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

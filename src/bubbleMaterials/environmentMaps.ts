import {
  ClampToEdgeWrapping,
  DataTexture,
  DataUtils,
  FloatType,
  HalfFloatType,
  LinearFilter,
  LinearSRGBColorSpace,
  RepeatWrapping,
  RGBAFormat,
} from 'three';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';
import { type HdrEnvironment } from '../environments/environments.ts';
import { mapSource } from '../environments/hdrMaps.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';

/** An equirectangular radiance map: RGBA float texels, row 0 at the bottom (v = 0 looks straight down). */
export interface EnvironmentPixels {
  readonly width: number;
  readonly height: number;
  readonly rgba: Float32Array;
}

const loads = new Map<HdrEnvironment, Promise<EnvironmentPixels>>();
const loaded = new Map<HdrEnvironment, EnvironmentPixels>();

/** Decodes a data URL without fetch (which a page's Content-Security-Policy may forbid for data:). */
function dataUrlBytes(url: string): ArrayBuffer {
  const binary = atob(url.slice(url.indexOf(',') + 1));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

/**
 * The environment's radiance, fetched and decoded once per page (three's EXRLoader). A load that
 * fails rejects, and is tried again the next time it is asked for.
 */
export function loadEnvironmentPixels(name: HdrEnvironment): Promise<EnvironmentPixels> {
  let load = loads.get(name);
  if (!load) {
    load = mapSource(name)().then((module) => {
      const exr = new EXRLoader().setDataType(FloatType).parse(dataUrlBytes(module.default));
      if (!(exr.data instanceof Float32Array) || exr.format !== RGBAFormat) throw new Error(`${name}: not an RGBA float EXR`);
      // The maps ring around the sun and lamps (negative texels, down to −1876 in park): radiance is
      // never negative, so those are clipped to 0 (a negative sun would draw black through AgX).
      for (let i = 0; i < exr.data.length; i++) if (exr.data[i]! < 0) exr.data[i] = 0;
      const pixels = { width: exr.width ?? 0, height: exr.height ?? 0, rgba: exr.data };
      loaded.set(name, pixels);
      return pixels;
    });
    load.catch(() => loads.delete(name));
    loads.set(name, load);
  }
  return load;
}

/** Half floats: filterable on every WebGL2 GPU (float32 needs OES_texture_float_linear). */
const textures = new SharedTextures((key) => {
  const pixels = loaded.get(key as HdrEnvironment);
  if (!pixels) throw new Error(`environment ${key} is not loaded`);
  const half = new Uint16Array(pixels.rgba.length);
  for (let i = 0; i < half.length; i++) half[i] = DataUtils.toHalfFloat(pixels.rgba[i]!);
  const texture = new DataTexture(half, pixels.width, pixels.height, RGBAFormat, HalfFloatType);
  texture.colorSpace = LinearSRGBColorSpace;
  texture.wrapS = RepeatWrapping; // around the horizon
  texture.wrapT = ClampToEdgeWrapping; // at the poles
  texture.magFilter = texture.minFilter = LinearFilter;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
});

/** Whether an HDR environment's pixels have arrived (its texture is then at hand). */
export const environmentLoaded = (name: HdrEnvironment): boolean => loaded.has(name);

/** The loaded environment as a texture, shared by its holders; null until it has arrived. */
export function environmentTexture(name: HdrEnvironment, holder: object): DataTexture | null {
  return loaded.has(name) ? textures.hold(name, holder) : null;
}

/** `holder` needs no environment texture any more. */
export const releaseEnvironmentTexture = (holder: object): void => textures.release(holder);

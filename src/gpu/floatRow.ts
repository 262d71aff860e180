import { DataTexture, FloatType, NearestFilter, RGBAFormat, type ShaderMaterial, WebGLRenderTarget, type WebGLRenderer } from 'three';
import { FullscreenPass } from './fullscreenPass.ts';

/** RGBA float texels (row-major, 4 floats each), read by texelFetch (no filtering). */
export function floatTexture(data: Float32Array, width: number, height: number): DataTexture {
  const texture = new DataTexture(data, width, height, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
}

/** One row of RGBA float texels: a shader's per-case inputs. */
export function floatRowTexture(rgba: readonly (readonly number[])[]): DataTexture {
  const data = new Float32Array(4 * rgba.length);
  rgba.forEach((texel, i) => data.set(texel, 4 * i));
  return floatTexture(data, rgba.length, 1);
}

/**
 * What `draw` draws into a row of `count` float pixels (RGBA per pixel, no colour conversion), read
 * back; `depthBuffer` for a scene whose meshes hide one another.
 */
export function readFloatRow(renderer: WebGLRenderer, count: number, draw: () => void, depthBuffer = false): Float32Array {
  const target = new WebGLRenderTarget(count, 1, { type: FloatType, format: RGBAFormat, depthBuffer });
  renderer.setRenderTarget(target);
  draw();
  const out = new Float32Array(4 * count);
  renderer.readRenderTargetPixels(target, 0, 0, count, 1, out);
  renderer.setRenderTarget(null);
  target.dispose();
  return out;
}

/**
 * Draws `material` over a row of `count` float pixels and reads them back: how the parity checks
 * see a shader's own numbers.
 */
export function renderFloatRow(renderer: WebGLRenderer, material: ShaderMaterial, count: number): Float32Array {
  const pass = new FullscreenPass();
  const out = readFloatRow(renderer, count, () => pass.render(renderer, material));
  pass.dispose();
  return out;
}

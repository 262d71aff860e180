/**
 * The materials page's renderer: WebGLRenderer with the WebGL entry, or with `?renderer=webgpu`
 * three.js's WebGPURenderer (WebGPU, or its WebGL2 backend) with the WebGPU entry, loaded only then.
 */
import { type Material, WebGLRenderer } from 'three';
import type { WebGPURenderer } from 'three/webgpu';
import { spectralIridescence, whenSpectralReady } from '../meshMaterial/spectralIridescence.ts';
import { type Upgrade } from './materialsScene.ts';

export interface PageRenderer {
  readonly renderer: WebGLRenderer | WebGPURenderer;
  /** which renderer draws the page, as the readout names it */
  readonly name: string;
  readonly upgrade: Upgrade;
  /** When a spectral material of the page can be drawn settled: its entry's whenSpectralReady. */
  readonly whenReady: (m: Material) => Promise<void>;
  /** The 8-bit pixel drawn at (x, y) device pixels from the canvas's bottom left, read at once; null where the canvas cannot be read at once (WebGPU). */
  readonly readPixel: (x: number, y: number) => number[] | null;
}

/** WebGLRenderer and the WebGL entry: the page's pixels read back at once. */
function webglRenderer(canvas: HTMLCanvasElement): PageRenderer {
  const renderer = new WebGLRenderer({ canvas, antialias: true });
  const readPixel = (x: number, y: number) => {
    const gl = renderer.getContext();
    const out = new Uint8Array(4);
    gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return [out[0]!, out[1]!, out[2]!];
  };
  return { renderer, name: 'WebGLRenderer', upgrade: spectralIridescence, whenReady: whenSpectralReady, readPixel };
}

/** WebGPURenderer and the WebGPU entry, once the renderer has its backend. */
async function webgpuRenderer(canvas: HTMLCanvasElement): Promise<PageRenderer> {
  const [{ WebGPURenderer }, { spectralIridescence: nodeEntry, whenSpectralReady: nodeReady }] = await Promise.all([
    import('three/webgpu'),
    import('../nodeMaterial/spectralNodeMaterial.ts'),
  ]);
  const renderer = new WebGPURenderer({ canvas, antialias: true });
  await renderer.init();
  const backend = (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend ? 'WebGPU' : 'WebGL2';
  return { renderer, name: `WebGPURenderer (${backend})`, upgrade: nodeEntry, whenReady: nodeReady, readPixel: () => null };
}

/** The renderer the page's URL asks for. */
export const pageRenderer = (canvas: HTMLCanvasElement): Promise<PageRenderer> =>
  new URLSearchParams(location.search).get('renderer') === 'webgpu' ? webgpuRenderer(canvas) : Promise.resolve(webglRenderer(canvas));

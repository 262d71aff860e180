import {
  FloatType,
  type Mesh,
  type PerspectiveCamera,
  RGBAFormat,
  ShaderMaterial,
  type SphereGeometry,
  type WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import type { Xyz } from '../physics/spectralWeights.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { bubbleHit } from './bubbleRay.ts';

/** What the bubble shows at one point of the view: the near wall's film there. */
export interface ProbeReading {
  readonly thicknessNm: number;
  readonly angleDeg: number;
  /** The film's XYZ as the shader computes it there (before exposure), read from a float target. */
  readonly renderedXyz: Xyz;
}

/** The film at the probe without the GPU's colour: what a bubble's `probechange` event carries. */
export type ProbedFilm = Pick<ProbeReading, 'thicknessNm' | 'angleDeg'>;

/** How often a probe's fence is polled (ms): a few times a frame. */
const FENCE_POLL_MS = 4;

/**
 * The RGBA float pixel at (0, 0) of the render target bound: copied into a pixel-pack buffer
 * behind a fence (gl.fenceSync), which is polled with clientWaitSync and timeout 0 until it is
 * signalled; then the buffer is read (getBufferSubData). Rejects if the context is lost
 * meanwhile, touching none of the lost context's objects (three's readRenderTargetPixelsAsync
 * would delete them in the restored context, which WebGL warns about).
 */
function readPixelAsync(renderer: WebGLRenderer): Promise<Float32Array> {
  const gl = renderer.getContext() as WebGL2RenderingContext;
  const buffer = gl.createBuffer();
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
  gl.bufferData(gl.PIXEL_PACK_BUFFER, 4 * Float32Array.BYTES_PER_ELEMENT, gl.STREAM_READ);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, 0);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  const canvas = renderer.domElement;
  let lost = gl.isContextLost() || sync === null;
  const onLost = () => (lost = true);
  canvas.addEventListener('webglcontextlost', onLost);
  return new Promise((resolve, reject) => {
    const poll = () => {
      const status = lost ? gl.WAIT_FAILED : gl.clientWaitSync(sync!, 0, 0);
      if (status === gl.TIMEOUT_EXPIRED) return void setTimeout(poll, FENCE_POLL_MS);
      canvas.removeEventListener('webglcontextlost', onLost);
      if (lost) return reject(new Error('the WebGL context was lost before the probe’s pixel came back'));
      const pixel = new Float32Array(4);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
      gl.getBufferSubData(gl.PIXEL_PACK_BUFFER, 0, pixel);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
      gl.deleteSync(sync);
      gl.deleteBuffer(buffer);
      if (status === gl.WAIT_FAILED) reject(new Error('the probe’s fence failed'));
      else resolve(pixel);
    };
    setTimeout(poll, FENCE_POLL_MS);
  });
}

/**
 * θ_i where the view ray through (fx, fy) (fractions of the view, from the top left) meets the
 * unit bubble, or null where it misses: the angle between the ray and the sphere's normal.
 */
export function incidenceAngleDeg(camera: PerspectiveCamera, fx: number, fy: number): number | null {
  const hit = bubbleHit(camera, [fx, fy]);
  if (!hit) return null;
  const cos = Math.min(1, Math.abs(hit.point.clone().normalize().dot(hit.ray.direction)));
  return (Math.acos(cos) * 180) / Math.PI;
}

/**
 * Reads the film at one pixel back from the GPU: the bubble is drawn once more through a
 * 1-pixel window of the camera (setViewOffset) with the material's TFC_PROBE output — the near
 * wall's film XYZ and thickness — into a 1×1 float target, read back without waiting for the GPU
 * (readPixelAsync), so the frames go on meanwhile.
 */
export class FilmProbe {
  private readonly target = new WebGLRenderTarget(1, 1, { type: FloatType, format: RGBAFormat });
  private material: ShaderMaterial | null = null;

  /**
   * The film at (fx, fy) (fractions of the view from the top left) as the bubble is drawn now: null
   * off the bubble; rejects if the context is lost before the pixel is back.
   */
  async read(
    renderer: WebGLRenderer,
    camera: PerspectiveCamera,
    bubble: Mesh<SphereGeometry, ShaderMaterial>,
    viewSize: { width: number; height: number },
    fx: number,
    fy: number,
  ): Promise<ProbeReading | null> {
    const angleDeg = incidenceAngleDeg(camera, fx, fy);
    if (angleDeg === null) return null;
    const { width, height } = viewSize;
    const x = Math.min(width - 1, Math.floor(fx * width));
    const y = Math.min(height - 1, Math.floor(fy * height));
    camera.setViewOffset(width, height, x, y, 1, 1);
    const read = this.drawingProbe(renderer, bubble, () => {
      renderer.clear();
      renderer.render(bubble, camera);
      return readPixelAsync(renderer);
    });
    camera.clearViewOffset();
    const pixel = await read;
    return { thicknessNm: pixel[3]!, angleDeg, renderedXyz: [pixel[0]!, pixel[1]!, pixel[2]!] };
  }

  /** Compiles the probe's program for the bubble's defines now, without blocking where the GPU compiles in parallel. */
  compileAsync(renderer: WebGLRenderer, camera: PerspectiveCamera, bubble: Mesh<SphereGeometry, ShaderMaterial>): Promise<unknown> {
    return this.drawingProbe(renderer, bubble, () => renderer.compileAsync(bubble, camera));
  }

  /** `act` with the bubble given the probe's material and the renderer the probe's target (three picks a program by both), both put back after. */
  private drawingProbe<T>(renderer: WebGLRenderer, bubble: Mesh<SphereGeometry, ShaderMaterial>, act: () => T): T {
    const shown = bubble.material;
    bubble.material = this.probeMaterial(shown);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    try {
      return act();
    } finally {
      renderer.setRenderTarget(previous);
      bubble.material = shown;
    }
  }

  /** The bubble's material with TFC_PROBE defined, sharing its uniforms; follows its defines. */
  private probeMaterial(shown: ShaderMaterial): ShaderMaterial {
    this.material ??= new ShaderMaterial({
      uniforms: shown.uniforms,
      vertexShader: shown.vertexShader,
      fragmentShader: shown.fragmentShader,
    });
    setDefines(this.material, { ...shown.defines, TFC_PROBE: 1 });
    return this.material;
  }

  dispose(): void {
    this.target.dispose();
    this.material?.dispose();
  }
}

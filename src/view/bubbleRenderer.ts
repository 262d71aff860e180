import { WebGLRenderer } from 'three';

/**
 * A WebGL2 renderer for bubbles on a canvas (the drawing buffer is kept for screenshots and reads).
 * Where the GPU compiles in parallel, its views check their programs' links themselves
 * (src/gpu/linkFailures.ts) instead of three's check at the first draw, which would wait for the GPU.
 */
export function createBubbleRenderer(canvas: HTMLCanvasElement): WebGLRenderer {
  const renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  if (renderer.extensions.has('KHR_parallel_shader_compile')) renderer.debug.checkShaderErrors = false;
  return renderer;
}

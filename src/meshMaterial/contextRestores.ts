import type { WebGLRenderer } from 'three';

const counts = new WeakMap<WebGLRenderer, number>();

/**
 * How many times `renderer`'s WebGL context has been restored since this was first asked about
 * it. three re-creates programs and re-uploads textures after a restore by itself; what was drawn
 * on the GPU (a film table) is gone, and a count that moved tells its holder to draw it again.
 */
export function restoresOf(renderer: WebGLRenderer): number {
  const known = counts.get(renderer);
  if (known !== undefined) return known;
  counts.set(renderer, 0);
  renderer.domElement.addEventListener('webglcontextrestored', () => counts.set(renderer, counts.get(renderer)! + 1));
  return 0;
}

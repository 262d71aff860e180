/**
 * The spectral material's harness pages' renderer (tests/e2e/harness/material.html): one
 * WebGLRenderer on the page's canvas, a film case's scene (filmCaseScene.ts) drawn and read back
 * as 8-bit pixels.
 */
import { NoToneMapping, type OrthographicCamera, type PerspectiveCamera, type Scene, WebGLRenderer } from 'three';

const canvas = document.querySelector<HTMLCanvasElement>('#gl');
if (!canvas) throw new Error('material.html must hold #gl');
export const renderer = new WebGLRenderer({ canvas });
renderer.toneMapping = NoToneMapping;
const SIZE = canvas.width;

/** The canvas's pixels (RGBA, bottom row first) right after drawing `scene`. */
export function draw(scene: Scene, camera: OrthographicCamera | PerspectiveCamera): Uint8Array {
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const out = new Uint8Array(4 * SIZE * SIZE);
  gl.readPixels(0, 0, SIZE, SIZE, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return out;
}

export const centre = (pixels: Uint8Array): number[] => {
  const i = 4 * ((SIZE / 2) * SIZE + SIZE / 2);
  return [pixels[i]!, pixels[i + 1]!, pixels[i + 2]!];
};

/**
 * The WebGL entry's material drawn by three's WebGPURenderer (three/webgpu) on its WebGL2 backend
 * (`forceWebGL`, which the tests' ordinary browser offers): what it says in the console.
 */
import { MeshPhysicalMaterial } from 'three';
import { WebGPURenderer } from 'three/webgpu';
import { spectralIridescence } from '../../../src/meshMaterial/spectralIridescence.ts';
import { type FilmCase, disposeAll, filmMaterial, filmScene } from './filmCaseScene.ts';

/**
 * The console's warnings while a WebGPURenderer draws the film case twice with the spectral
 * material, then once with three's own; the renderer and its canvas are let go after.
 */
export async function nodeRendererWarnings(c: FilmCase): Promise<{ spectral: string[]; threes: string[] }> {
  const renderer = new WebGPURenderer({ canvas: document.createElement('canvas'), forceWebGL: true });
  renderer.setSize(8, 8, false);
  await renderer.init();
  const warned: string[] = [];
  const warn = console.warn;
  console.warn = (...args: unknown[]) => void warned.push(args.map(String).join(' '));
  try {
    const drawn = (material: MeshPhysicalMaterial, times: number) => {
      const { scene, camera } = filmScene(c, material);
      for (let i = 0; i < times; i++) renderer.render(scene, camera);
      disposeAll(scene);
      return warned.splice(0);
    };
    const spectral = drawn(spectralIridescence(filmMaterial(c)), 2);
    const threes = drawn(filmMaterial(c), 1);
    return { spectral, threes };
  } finally {
    console.warn = warn;
    void renderer.dispose();
  }
}

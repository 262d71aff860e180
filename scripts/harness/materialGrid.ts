/**
 * The error grids through the whole spectral material on WebGLRenderer (materialGridScene.ts),
 * read from a float target.
 */
import { FloatType, MeshPhysicalMaterial, WebGLRenderTarget, WebGLRenderer } from 'three';
import type { ParityGroup, ParityMode } from './parityCase.ts';
import { spectralIridescence, whenSpectralReady } from '../../src/meshMaterial/spectralIridescence.ts';
import { type DrawRow, gridMaterialParameters, gridXyz } from './materialGridScene.ts';

const renderer = new WebGLRenderer({ canvas: document.querySelector<HTMLCanvasElement>('#gl')! });

const drawRow: DrawRow = (scene, camera, width) => {
  const target = new WebGLRenderTarget(width, 1, { type: FloatType, depthBuffer: true });
  renderer.setRenderTarget(target);
  renderer.render(scene, camera);
  const rgba = new Float32Array(4 * width);
  renderer.readRenderTargetPixels(target, 0, 0, width, 1, rgba);
  renderer.setRenderTarget(null);
  target.dispose();
  return Promise.resolve(rgba);
};

/** XYZ per input of the group; one material for the group (one program, one film table). */
async function materialGridXyz(g: ParityGroup, mode: Exclude<ParityMode, 'three-iridescence'>): Promise<number[][]> {
  const { illuminant, lightTint, polarization, normalization } = g;
  const material = spectralIridescence(new MeshPhysicalMaterial(gridMaterialParameters(g)), {
    mode,
    illuminant,
    lightTint,
    polarization,
    normalization,
  });
  await whenSpectralReady(material);
  const out = await gridXyz(g, material, drawRow);
  material.dispose();
  return out;
}

window.materialGridXyz = materialGridXyz;
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    materialGridXyz?: typeof materialGridXyz;
  }
}

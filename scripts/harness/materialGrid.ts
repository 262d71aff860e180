/**
 * The error grids through the whole spectral material on WebGLRenderer (materialGridScene.ts),
 * read from a float target.
 */
import { MeshPhysicalMaterial, WebGLRenderer } from 'three';
import { readFloatRow } from '../../src/gpu/floatRow.ts';
import type { ParityGroup, ParityMode } from './parityCase.ts';
import { spectralIridescence, whenSpectralReady } from '../../src/meshMaterial/spectralIridescence.ts';
import { type DrawRow, gridMaterialParameters, gridXyz } from './materialGridScene.ts';

const renderer = new WebGLRenderer({ canvas: document.querySelector<HTMLCanvasElement>('#gl')! });

const drawRow: DrawRow = (scene, camera, width) =>
  Promise.resolve(readFloatRow(renderer, width, () => renderer.render(scene, camera), true));

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

/**
 * The error grids through the whole spectral material (not only its film term): for each angle,
 * a plane tilted by θ about the screen's x axis, seen by an orthographic camera, one pixel per
 * film; a float thickness map gives each pixel its thickness (green channel, nearest texel); the
 * base is black, mirror-smooth, non-metal, lit by an environment of constant radiance 1, so the
 * linear pixel is the film's reflectance as three's lighting passes it on (DFG, multiple
 * scattering) and as the material clips it. Read from a float target; XYZ by eq (19) inverted.
 */
import {
  DataTexture,
  EquirectangularReflectionMapping,
  FloatType,
  Mesh,
  MeshPhysicalMaterial,
  NearestFilter,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  Scene,
  WebGLRenderTarget,
  WebGLRenderer,
} from 'three';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from '../../src/physics/colorConversions.ts';
import type { Medium } from '../../src/physics/medium.ts';
import type { ParityGroup, ParityMode } from './parityCase.ts';
import { spectralIridescence, whenSpectralReady } from '../../src/meshMaterial/spectralIridescence.ts';

/** The material's indices are three's iridescenceIOR and ior, numbers: the grids must be of constant real media. */
function constantIndex(index: Medium): number {
  if (typeof index !== 'number') throw new Error(`the material's grids take a constant real index, not ${JSON.stringify(index)}`);
  return index;
}

const renderer = new WebGLRenderer({ canvas: document.querySelector<HTMLCanvasElement>('#gl')! });
const LINEAR_SRGB_TO_XYZ = invert3(XYZ_TO_LINEAR_SRGB);

function floatTexture(width: number, texel: (i: number) => readonly number[]): DataTexture {
  const data = new Float32Array(4 * width);
  for (let i = 0; i < width; i++) data.set(texel(i), 4 * i);
  const t = new DataTexture(data, width, 1, RGBAFormat, FloatType);
  t.minFilter = t.magFilter = NearestFilter;
  t.needsUpdate = true;
  return t;
}

/** XYZ per input of the group (a soap film in air: the base's ior is the group's nInside). */
async function materialGridXyz(g: ParityGroup, mode: Exclude<ParityMode, 'three-iridescence'>): Promise<number[][]> {
  const white = floatTexture(16, () => [1, 1, 1, 1]);
  white.mapping = EquirectangularReflectionMapping;
  const maxNm = Math.max(...g.inputs.map(([t]) => t), 1);
  const byCos = new Map<number, number[]>();
  g.inputs.forEach(([, c], i) => byCos.set(c, [...(byCos.get(c) ?? []), i]));
  const out: number[][] = new Array<number[]>(g.inputs.length);
  // One material for the group (one program, one film table); each angle swaps its thickness map.
  const material = spectralIridescence(
    new MeshPhysicalMaterial({
      color: 0x000000,
      roughness: 0,
      metalness: 0,
      ior: constantIndex(g.nInside),
      iridescence: 1,
      iridescenceIOR: constantIndex(g.nFilm),
      iridescenceThicknessMinimum: 0,
      iridescenceThicknessMaximum: maxNm,
    }),
    { mode, illuminant: g.illuminant, lightTint: g.lightTint, polarization: g.polarization, normalization: g.normalization },
  );
  await whenSpectralReady(material);
  const plane = new Mesh(new PlaneGeometry(2, 4), material);
  const scene = new Scene();
  scene.environment = white;
  scene.add(plane);
  const camera = new OrthographicCamera(-1, 1, 1e-3, -1e-3, -10, 10);
  for (const [cos, cases] of byCos) {
    const w = cases.length;
    const map = floatTexture(w, (i) => [0, g.inputs[cases[i]!]![0] / maxNm, 0, 1]);
    material.iridescenceThicknessMap = map;
    plane.rotation.x = Math.acos(Math.min(1, cos));
    const target = new WebGLRenderTarget(w, 1, { type: FloatType, depthBuffer: true });
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    const rgba = new Float32Array(4 * w);
    renderer.readRenderTargetPixels(target, 0, 0, w, 1, rgba);
    renderer.setRenderTarget(null);
    cases.forEach((c, i) => (out[c] = [...applyMatrix3(LINEAR_SRGB_TO_XYZ, [rgba[4 * i]!, rgba[4 * i + 1]!, rgba[4 * i + 2]!])]));
    target.dispose();
    map.dispose();
  }
  plane.geometry.dispose();
  material.dispose();
  white.dispose();
  return out;
}

window.materialGridXyz = materialGridXyz;
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    materialGridXyz?: typeof materialGridXyz;
  }
}

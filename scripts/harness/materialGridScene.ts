/**
 * The error grids through a whole physical material (not only its film term), for any renderer
 * (materialGrid.ts draws them with WebGLRenderer, the benchmark's node page with WebGPURenderer):
 * for each angle, a plane tilted by θ about the screen's x axis, seen by an orthographic camera,
 * one pixel per film; a float thickness map gives each pixel its thickness (green channel, nearest
 * texel); the base is black, mirror-smooth, non-metal, lit by an environment of constant radiance
 * 1, so the linear pixel is the film's reflectance as three's lighting passes it on (DFG, multiple
 * scattering) and as the material clips it. XYZ by eq (19) inverted.
 */
import {
  type Camera,
  DataTexture,
  EquirectangularReflectionMapping,
  FloatType,
  type Material,
  Mesh,
  type MeshPhysicalMaterialParameters,
  NearestFilter,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  Scene,
  type Texture,
} from 'three';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from '../../src/physics/colorConversions.ts';
import type { Medium } from '../../src/physics/medium.ts';
import type { ParityGroup } from './parityCase.ts';

const LINEAR_SRGB_TO_XYZ = invert3(XYZ_TO_LINEAR_SRGB);

/** The material's indices are three's iridescenceIOR and ior, numbers: the grids must be of constant real media. */
function constantIndex(index: Medium): number {
  if (typeof index !== 'number') throw new Error(`the material's grids take a constant real index, not ${JSON.stringify(index)}`);
  return index;
}

function floatTexture(width: number, texel: (i: number) => readonly number[]): DataTexture {
  const data = new Float32Array(4 * width);
  for (let i = 0; i < width; i++) data.set(texel(i), 4 * i);
  const t = new DataTexture(data, width, 1, RGBAFormat, FloatType);
  t.minFilter = t.magFilter = NearestFilter;
  t.needsUpdate = true;
  return t;
}

/** The film's largest thickness over the grid (nm, at least 1): the thickness map's 1. */
const maxThicknessNm = (g: ParityGroup) => Math.max(...g.inputs.map(([t]) => t), 1);

/** The grid's material parameters: a soap film in air over a black mirror-smooth dielectric (the base's ior is the group's nInside). */
export const gridMaterialParameters = (g: ParityGroup): MeshPhysicalMaterialParameters => ({
  color: 0x000000,
  roughness: 0,
  metalness: 0,
  ior: constantIndex(g.nInside),
  iridescence: 1,
  iridescenceIOR: constantIndex(g.nFilm),
  iridescenceThicknessMinimum: 0,
  iridescenceThicknessMaximum: maxThicknessNm(g),
});

/** Draws `scene` into a float target `width`×1 and reads its RGBA back. */
export type DrawRow = (scene: Scene, camera: Camera, width: number) => Promise<Float32Array>;

/** XYZ per input of the group, drawn by `material` (of gridMaterialParameters); each angle swaps its thickness map, so one program serves all. */
export async function gridXyz(g: ParityGroup, material: Material & { iridescenceThicknessMap: Texture | null }, drawRow: DrawRow) {
  const white = floatTexture(16, () => [1, 1, 1, 1]);
  white.mapping = EquirectangularReflectionMapping;
  const maxNm = maxThicknessNm(g);
  const byCos = new Map<number, number[]>();
  g.inputs.forEach(([, c], i) => byCos.set(c, [...(byCos.get(c) ?? []), i]));
  const out: number[][] = new Array<number[]>(g.inputs.length);
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
    const rgba = await drawRow(scene, camera, w);
    cases.forEach((c, i) => (out[c] = [...applyMatrix3(LINEAR_SRGB_TO_XYZ, [rgba[4 * i]!, rgba[4 * i + 1]!, rgba[4 * i + 2]!])]));
    map.dispose();
  }
  plane.geometry.dispose();
  white.dispose();
  return out;
}

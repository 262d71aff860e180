/**
 * A film case's scene, for any renderer (tests/e2e/harness/materialScene.ts draws it with
 * WebGLRenderer, webgpu.ts with WebGPURenderer): a film on a box's face under constant white light.
 */
import {
  BoxGeometry,
  type BufferGeometry,
  DataTexture,
  EquirectangularReflectionMapping,
  FloatType,
  Mesh,
  MeshPhysicalMaterial,
  OrthographicCamera,
  RGBAFormat,
  Scene,
  type Material,
  type Object3D,
} from 'three';

/** An equirectangular float environment of `size` texels, each `texel(u, v)` (linear RGB). */
export function environment(texel: (u: number, v: number) => readonly [number, number, number], w = 32, h = 16): DataTexture {
  const data = new Float32Array(4 * w * h);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) data.set([...texel(x / w, y / h), 1], 4 * (y * w + x));
  const t = new DataTexture(data, w, h, RGBAFormat, FloatType);
  t.mapping = EquirectangularReflectionMapping;
  t.needsUpdate = true;
  return t;
}

/** Constant radiance 1 (the light's white from every direction): the demo's env=none lighting of the film. */
const white = environment(() => [1, 1, 1]);

/**
 * A film on a box's face, mirror-smooth: black and non-metal, so only the film reflects, or a metal
 * of `metalColor` (sRGB hex, metalness 1: the film over the metal from its colour).
 */
export interface FilmCase {
  readonly thicknessNm: number;
  readonly angleDeg: number;
  readonly nFilm: number;
  readonly ior: number;
  readonly metalColor?: number;
}

export const filmMaterial = <M extends Material = MeshPhysicalMaterial>(
  c: FilmCase,
  Kind: new (parameters: Record<string, unknown>) => M = MeshPhysicalMaterial as never,
): M =>
  new Kind({
    color: c.metalColor ?? 0x000000,
    roughness: 0,
    metalness: c.metalColor === undefined ? 0 : 1,
    ior: c.ior,
    iridescence: 1,
    iridescenceIOR: c.nFilm,
    iridescenceThicknessMinimum: 0,
    iridescenceThicknessMaximum: c.thicknessNm,
  });

/**
 * A 4-unit box turned by angleDeg about the vertical, its front face through the origin, seen
 * by an orthographic camera along −z: the centre pixel sees that face at θ_i = angleDeg.
 */
export function filmScene(c: FilmCase, material: Material): { scene: Scene; camera: OrthographicCamera; box: Mesh } {
  const scene = new Scene();
  scene.environment = white;
  const box = new Mesh(new BoxGeometry(4, 4, 4), material);
  const a = (c.angleDeg * Math.PI) / 180;
  box.rotation.y = a;
  box.position.set(-2 * Math.sin(a), 0, -2 * Math.cos(a));
  scene.add(box);
  const camera = new OrthographicCamera(-1, 1, 1, -1, 0.1, 20);
  camera.position.set(0, 0, 10);
  return { scene, camera, box };
}

export const disposeAll = (root: Object3D) =>
  root.traverse((o) => {
    if (o instanceof Mesh) {
      const mesh = o as Mesh<BufferGeometry, Material | Material[]>;
      mesh.geometry.dispose();
      for (const m of [mesh.material].flat()) m.dispose();
    }
  });

/**
 * The node figures' scene (nodeBench.ts): an iridescent sphere filling the view of WebGPURenderer,
 * lit by a constant white environment and a directional light, drawn with each of NODE_MATERIALS:
 * the floor (the same MeshPhysicalNodeMaterial without iridescence), three.js's node iridescence,
 * and the WebGPU entry's film in `table` and in `exact`. A frame is drawn into a float target and
 * ends with a 1-pixel read, so it is timed to the GPU's end on either backend.
 */
import {
  DataTexture,
  DirectionalLight,
  EquirectangularReflectionMapping,
  FloatType,
  Mesh,
  PerspectiveCamera,
  RGBAFormat,
  RenderTarget,
  Scene,
  SphereGeometry,
} from 'three';
import { MeshPhysicalNodeMaterial, type WebGPURenderer } from 'three/webgpu';
import { type FilmQuality, spectralIridescence, whenSpectralReady } from '../../../src/packageEntries/webgpu.ts';
import { NODE_MATERIALS, type NodeMaterialName } from '../nodeMaterials.ts';

/** A soap film over a glossy grey dielectric, its thickness across the sphere by a thickness map (glTF: green, min → max). */
const FILM = {
  color: 0x404040,
  roughness: 0.2,
  metalness: 0,
  ior: 1.5,
  iridescenceIOR: 1.33,
  iridescenceThicknessMinimum: 100,
  iridescenceThicknessMaximum: 800,
} as const;

/** A 64-texel ramp of green 0 → 1 along u: the film's thickness over its range. */
function thicknessMap(): DataTexture {
  const data = new Uint8Array(4 * 64);
  for (let i = 0; i < 64; i++) data.set([0, Math.round((255 * i) / 63), 0, 255], 4 * i);
  const t = new DataTexture(data, 64, 1);
  t.needsUpdate = true;
  return t;
}

/** A float equirectangular environment of constant radiance 1. */
function whiteEnvironment(): DataTexture {
  const t = new DataTexture(new Float32Array(4 * 32 * 16).fill(1), 32, 16, RGBAFormat, FloatType);
  t.mapping = EquirectangularReflectionMapping;
  t.needsUpdate = true;
  return t;
}

/** The material of each of NODE_MATERIALS. */
function materials(map: DataTexture, quality: FilmQuality): Record<NodeMaterialName, MeshPhysicalNodeMaterial> {
  const physical = (iridescence: number) => new MeshPhysicalNodeMaterial({ ...FILM, iridescence, iridescenceThicknessMap: map });
  return {
    floor: physical(0),
    'three.js': physical(1),
    table: spectralIridescence(physical(1), { mode: 'table', quality }),
    exact: spectralIridescence(physical(1), { mode: 'exact', quality }),
  };
}

export interface NodeScene {
  readonly materials: Record<NodeMaterialName, MeshPhysicalNodeMaterial>;
  /** Draws the sphere with material `name` into the target and reads one pixel back: the frame is done when it resolves. */
  draw(name: NodeMaterialName): Promise<void>;
  /** Draws with `name` until its spectral film is ready (whenSpectralReady; at once for three's), then once more. */
  drawReady(name: NodeMaterialName): Promise<void>;
  dispose(): void;
}

/** The scene at `width`×`height`, its spectral films of `quality`. */
export function nodeScene(renderer: WebGPURenderer, width: number, height: number, quality: FilmQuality): NodeScene {
  const map = thicknessMap();
  const byName = materials(map, quality);
  const scene = new Scene();
  scene.environment = whiteEnvironment();
  const light = new DirectionalLight(0xffffff, 2);
  light.position.set(1, 1, 2);
  scene.add(light);
  const sphere = new Mesh(new SphereGeometry(1, 64, 32), byName.floor);
  scene.add(sphere);
  const camera = new PerspectiveCamera(30, width / height, 0.1, 10);
  camera.position.z = 1 / Math.sin((15 * Math.PI) / 180);
  const target = new RenderTarget(width, height, { type: FloatType });
  const draw = async (name: NodeMaterialName) => {
    sphere.material = byName[name];
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    renderer.setRenderTarget(null);
    await renderer.readRenderTargetPixelsAsync(target, width >> 1, height >> 1, 1, 1);
  };
  return {
    materials: byName,
    draw,
    async drawReady(name) {
      const m = byName[name];
      let ready = !NODE_MATERIALS[name].spectral;
      if (!ready) void whenSpectralReady(m).then(() => (ready = true));
      while (!ready) await draw(name);
      await draw(name);
    },
    dispose() {
      sphere.geometry.dispose();
      for (const m of Object.values(byName)) m.dispose();
      map.dispose();
      scene.environment?.dispose();
      target.dispose();
    },
  };
}

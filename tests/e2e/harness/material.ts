/**
 * The spectral iridescence's harness (tests/e2e/material.spec.ts): scenes of three.js meshes
 * drawn with MeshPhysicalMaterial, with and without `spectralIridescence`, read back as 8-bit
 * pixels of the canvas.
 */
import {
  BoxGeometry,
  Color,
  DataTexture,
  DirectionalLight,
  Mesh,
  MeshPhysicalMaterial,
  NoToneMapping,
  PCFShadowMap,
  PerspectiveCamera,
  PlaneGeometry,
  PointLight,
  RepeatWrapping,
  Scene,
  TorusKnotGeometry,
  AgXToneMapping,
} from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { spectralIridescence, useSpectralIridescence, whenSpectralReady } from '../../../src/meshMaterial/spectralIridescence.ts';
import { type SpectralIridescenceOptions } from '../../../src/meshMaterial/spectralIridescenceOptions.ts';
import { type FilmCase, disposeAll, environment, filmMaterial, filmScene } from './filmCaseScene.ts';
import { centre, draw, renderer } from './materialScene.ts';
import { nodeRendererWarnings } from './materialNodeRenderer.ts';
import { threeJsUserPixels } from './materialThreeJsUser.ts';

/** A task later: the page's other work (a chunk's arrival) runs between two frames. */
const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

/**
 * The film case through a material made spectral before the film's drawing is loaded (the page's
 * first): frames drawn while whenSpectralReady is pending, then the first frame after it is kept
 * and one drawn later (more frames and time apart), which should both show the settled film.
 */
async function readyPixels(c: FilmCase): Promise<{ waited: number; next: number[]; settled: number[] }> {
  const material = spectralIridescence(filmMaterial(c));
  const { scene, camera } = filmScene(c, material);
  let ready = false;
  const kept = whenSpectralReady(material).then(() => (ready = true));
  let waited = 0;
  for (; !ready; waited++) {
    draw(scene, camera);
    await nextTask();
  }
  await kept;
  const next = centre(draw(scene, camera));
  for (let i = 0; i < 5; i++) draw(scene, camera);
  await new Promise((resolve) => setTimeout(resolve, 100));
  const settled = centre(draw(scene, camera));
  disposeAll(scene);
  return { waited, next, settled };
}

/** The centre pixel of a film case through the spectral material (the film's drawing loaded: readyPixels first). */
function filmPixel(c: FilmCase, options: SpectralIridescenceOptions): number[] {
  const { scene, camera } = filmScene(c, spectralIridescence(filmMaterial(c), options));
  const pixel = centre(draw(scene, camera));
  disposeAll(scene);
  return pixel;
}

/**
 * The rooms' environments, each made once for the page: three's PMREM of each new environment
 * texture, made and disposed draw after draw, leaves the texture units counted up (three r187 warns
 * of more than the GPU has after a few dozen), so a room is one texture however often it is drawn.
 */
const rooms = new Map<string, DataTexture>();

/**
 * The centre pixel of a film case through the spectral material in a uniform room of `room` (linear
 * RGB from every direction: scene.environment), the only light it reflects.
 */
function roomPixel(c: FilmCase, room: readonly [number, number, number], options: SpectralIridescenceOptions): number[] {
  const key = room.join();
  if (!rooms.has(key))
    rooms.set(
      key,
      environment(() => room),
    );
  const { scene, camera } = filmScene(c, spectralIridescence(filmMaterial(c), options));
  scene.environment = rooms.get(key)!;
  const pixel = centre(draw(scene, camera));
  disposeAll(scene);
  return pixel;
}

/** The centre pixel of the film case written to glTF (GLTFExporter), loaded back (GLTFLoader) and upgraded with one call. */
async function gltfPixel(c: FilmCase): Promise<{ pixel: number[]; upgraded: number; extension: boolean }> {
  const { scene: source, box } = filmScene(c, filmMaterial(c));
  const glb = (await new GLTFExporter().parseAsync(box, { binary: true })) as ArrayBuffer;
  const json = new TextDecoder().decode(new Uint8Array(glb, 20, new DataView(glb).getUint32(12, true)));
  const gltf = await new GLTFLoader().parseAsync(glb, '');
  disposeAll(source);
  const upgraded = useSpectralIridescence(gltf.scene);
  const { scene, camera } = filmScene(c, new MeshPhysicalMaterial());
  scene.clear();
  scene.add(gltf.scene);
  const pixel = centre(draw(scene, camera));
  disposeAll(scene);
  return { pixel, upgraded: upgraded.length, extension: json.includes('"KHR_materials_iridescence"') };
}

/** A small random normal map (seeded), so the comparison covers perturbed normals. */
function normalMap(): DataTexture {
  let seed = 7;
  const next = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
  const data = new Uint8Array(4 * 16 * 16);
  for (let i = 0; i < 16 * 16; i++)
    data.set([128 + Math.round(60 * (next() - 0.5)), 128 + Math.round(60 * (next() - 0.5)), 255, 255], 4 * i);
  const t = new DataTexture(data, 16, 16);
  t.wrapS = t.wrapT = RepeatWrapping;
  t.needsUpdate = true;
  return t;
}

/**
 * A lit scene (a torus knot with base colour, metalness, roughness, a normal map and clearcoat,
 * casting a shadow on a ground plane; a directional and a point light; a coloured environment;
 * AgX) drawn with `make()`'s material; the pixels.
 */
function litScene(make: () => MeshPhysicalMaterial): Uint8Array {
  const scene = new Scene();
  scene.environment = environment((u, v) => [0.2 + u, 0.5, 1.2 - v]);
  scene.background = new Color(0x202020);
  const knot = new Mesh(new TorusKnotGeometry(0.6, 0.2, 96, 12), make());
  knot.castShadow = true;
  const ground = new Mesh(new PlaneGeometry(4, 4), new MeshPhysicalMaterial({ color: 0x808080, roughness: 0.8 }));
  ground.rotation.x = -Math.PI / 2;
  ground.position.y = -1;
  ground.receiveShadow = true;
  const sun = new DirectionalLight(0xffffff, 2);
  sun.position.set(1, 3, 2);
  sun.castShadow = true;
  const lamp = new PointLight(0xffaa66, 4);
  lamp.position.set(-1.5, 0.5, 1.5);
  scene.add(knot, ground, sun, lamp);
  const camera = new PerspectiveCamera(45, 1, 0.1, 20);
  camera.position.set(0, 0.6, 3.2);
  camera.lookAt(0, -0.2, 0);
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = PCFShadowMap;
  renderer.toneMapping = AgXToneMapping;
  const pixels = draw(scene, camera);
  renderer.toneMapping = NoToneMapping;
  renderer.shadowMap.enabled = false;
  disposeAll(scene);
  return pixels;
}

/** The largest 8-bit difference between the physical material and the same upgraded, for the iridescence given. */
function againstPhysical(iridescence: number, thicknessMaximumNm: number): number {
  const map = normalMap();
  const make = () =>
    new MeshPhysicalMaterial({
      color: 0xc08040,
      metalness: 0.3,
      roughness: 0.35,
      normalMap: map,
      clearcoat: 0.5,
      iridescence,
      iridescenceThicknessMinimum: 0,
      iridescenceThicknessMaximum: thicknessMaximumNm,
    });
  const plain = litScene(make);
  const spectral = litScene(() => spectralIridescence(make()));
  map.dispose();
  let worst = 0;
  for (let i = 0; i < plain.length; i++) worst = Math.max(worst, Math.abs(plain[i]! - spectral[i]!));
  return worst;
}

const memory = () => ({ programs: renderer.info.programs?.length ?? 0, textures: renderer.info.memory.textures });

/**
 * Programs and textures as materials come and go: `count` boxes of the same film and options
 * (one program between them), then one per other mode; all disposed (back to the start).
 */
function programCounts(count: number, rounds: number) {
  const c: FilmCase = { thicknessNm: 400, angleDeg: 20, nFilm: 1.33, ior: 1.5 };
  const before = memory();
  const scene = filmScene(c, new MeshPhysicalMaterial());
  scene.scene.clear();
  const add = (options: SpectralIridescenceOptions) => {
    const box = new Mesh(new BoxGeometry(0.2, 0.2, 0.2), spectralIridescence(filmMaterial(c), options));
    scene.scene.add(box);
  };
  for (let i = 0; i < count; i++) add({ mode: 'table' });
  draw(scene.scene, scene.camera);
  const sameFilm = memory();
  add({ mode: 'fourier' });
  add({ mode: 'exact' });
  draw(scene.scene, scene.camera);
  const threeModes = memory();
  disposeAll(scene.scene);
  scene.scene.clear();
  draw(scene.scene, scene.camera);
  const disposed = memory();
  // The soak: materials of random modes, lights and films made, drawn and disposed.
  const modes = ['table', 'fourier', 'exact'] as const;
  const lights = ['D65', 'D55', { daylightCct: 7500 }] as const;
  let most = 0;
  for (let r = 0; r < rounds; r++) {
    const film = { ...c, thicknessNm: 100 + 37 * r, nFilm: 1.2 + (r % 5) * 0.1 };
    const box = new Mesh(
      new BoxGeometry(0.2, 0.2, 0.2),
      spectralIridescence(filmMaterial(film), { mode: modes[r % 3]!, illuminant: lights[r % 3]! }),
    );
    scene.scene.add(box);
    draw(scene.scene, scene.camera);
    most = Math.max(most, memory().programs);
    if (r % 2 === 1) {
      disposeAll(scene.scene);
      scene.scene.clear();
    }
  }
  disposeAll(scene.scene);
  scene.scene.clear();
  draw(scene.scene, scene.camera);
  return { before, sameFilm, threeModes, disposed, most, after: memory() };
}

/** Waits for `event` on the canvas after `act()`. */
function canvasEvent(event: 'webglcontextlost' | 'webglcontextrestored', act: () => void): Promise<void> {
  const happened = new Promise<void>((resolve) => renderer.domElement.addEventListener(event, () => resolve(), { once: true }));
  act();
  return happened;
}

/**
 * The centre pixel of a table-mode film case before the WebGL context is lost (WEBGL_lose_context)
 * and after it is restored, with the same material and film throughout: the table, drawn on the
 * GPU, is gone with the context and must be drawn again. The page's last check: its scene is not disposed.
 */
async function contextRestorePixels(c: FilmCase): Promise<{ before: number[]; after: number[] }> {
  const { scene, camera } = filmScene(c, spectralIridescence(filmMaterial(c), { mode: 'table' }));
  const before = centre(draw(scene, camera));
  const extension = renderer.getContext().getExtension('WEBGL_lose_context');
  if (!extension) throw new Error('WEBGL_lose_context is not offered');
  await canvasEvent('webglcontextlost', () => extension.loseContext());
  // The browser allows a restore only once the lost event's dispatch is over: a task later.
  await new Promise((resolve) => setTimeout(resolve, 0));
  await canvasEvent('webglcontextrestored', () => extension.restoreContext());
  const after = centre(draw(scene, camera));
  // Left as it is: three would delete objects of the lost context (browser warnings); the spec leaves the page next.
  return { before, after };
}

window.materialHarness = {
  readyPixels,
  filmPixel,
  roomPixel,
  gltfPixel,
  againstPhysical,
  programCounts,
  threeJsUserPixels,
  contextRestorePixels,
  nodeRendererWarnings,
};
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    materialHarness?: {
      readyPixels: typeof readyPixels;
      filmPixel: typeof filmPixel;
      roomPixel: typeof roomPixel;
      gltfPixel: typeof gltfPixel;
      againstPhysical: typeof againstPhysical;
      programCounts: typeof programCounts;
      threeJsUserPixels: typeof threeJsUserPixels;
      contextRestorePixels: typeof contextRestorePixels;
      nodeRendererWarnings: typeof nodeRendererWarnings;
    };
  }
}

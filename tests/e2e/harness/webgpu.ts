/**
 * The WebGPU entry's harness (tests/e2e/webgpu*.spec.ts): a film case drawn by WebGPURenderer (its
 * WebGPU backend, or with `forceWebGL` its WebGL2 one) into a float target and read back, with
 * three's node iridescence or the entry's film, on a MeshPhysicalNodeMaterial or a classic
 * MeshPhysicalMaterial; and, where the browser has WebGL2, the WebGL entry's film on WebGLRenderer
 * in the same scene; and the node film's XYZ of the parity cases (scripts/harness/nodeFilmProbe.ts).
 */
import {
  type Camera,
  FloatType,
  type Material,
  MeshPhysicalMaterial,
  NoToneMapping,
  RenderTarget,
  type Scene,
  type Texture,
  WebGLRenderTarget,
} from 'three';
import { float } from 'three/tsl';
import { MeshPhysicalNodeMaterial, NodeBuilder, WebGPURenderer } from 'three/webgpu';
import { type SpectralIridescenceOptions } from '../../../src/meshMaterial/spectralIridescenceOptions.ts';
import { spectralIridescence, whenSpectralReady } from '../../../src/nodeMaterial/spectralNodeMaterial.ts';
import { encode8 } from '../../../src/physics/colorConversions.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../../src/settings/filmQuality.ts';
import type { ParityGroup } from '../../../scripts/harness/parityCase.ts';
import { type FilmCase, disposeAll, environment, filmMaterial, filmScene } from './filmCaseScene.ts';
import { type NodeParityMode, renderNodeFilmXyz } from '../../../scripts/harness/nodeFilmProbe.ts';

const SIZE = 64;
/** 8-bit sRGB codes of linear RGB, clipped as a canvas clips. */
const codes = (linear: ArrayLike<number>): number[] => [0, 1, 2].map((i) => encode8(Math.min(1, Math.max(0, linear[i]!))));

let renderer: WebGPURenderer | null = null;

/** Starts WebGPURenderer on `backend`; the backend it runs on (a browser without a WebGPU adapter falls back to WebGL2). */
async function start(backend: 'webgpu' | 'webgl'): Promise<'webgpu' | 'webgl'> {
  void renderer?.dispose();
  renderer = new WebGPURenderer({ forceWebGL: backend === 'webgl' });
  renderer.toneMapping = NoToneMapping;
  await renderer.init();
  return (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend ? 'webgpu' : 'webgl';
}

/**
 * Which material: three's node iridescence, or the entry's film on a node or a classic material,
 * or on a node material whose thickness is a node (iridescenceThicknessNode: the case's thickness,
 * its thickness range's maximum a tenth of it).
 */
export type Kind = 'three' | 'node' | 'classic' | 'thicknessNode';

/** The material of film case `c` of kind `kind`. */
function materialOf(c: FilmCase, kind: Kind, options: SpectralIridescenceOptions): Material {
  if (kind === 'three') return filmMaterial(c, MeshPhysicalNodeMaterial);
  if (kind === 'classic') return spectralIridescence(filmMaterial(c), options);
  if (kind === 'node') return spectralIridescence(filmMaterial(c, MeshPhysicalNodeMaterial), options);
  const m = filmMaterial({ ...c, thicknessNm: c.thicknessNm / 10 }, MeshPhysicalNodeMaterial);
  m.iridescenceThicknessNode = float(c.thicknessNm);
  return spectralIridescence(m, options);
}

const floatTarget = () => new RenderTarget(SIZE, SIZE, { type: FloatType });

/**
 * The centre pixel of `scene` drawn by WebGPURenderer into a float target: linear RGB, and as
 * 8-bit sRGB. The target is `kept` (the caller's, drawn into again) or one made for this draw.
 */
async function drawCentre(scene: Scene, camera: Camera, kept: RenderTarget | null = null): Promise<{ linear: number[]; codes: number[] }> {
  const r = renderer!;
  const target = kept ?? floatTarget();
  r.setRenderTarget(target);
  r.render(scene, camera);
  r.setRenderTarget(null);
  const texels = (await r.readRenderTargetPixelsAsync(target, SIZE / 2, SIZE / 2, 1, 1)) as Float32Array;
  if (!kept) target.dispose();
  return { linear: [...texels.slice(0, 3)], codes: codes(texels) };
}

/** Uniform rooms, each one environment texture for the page (three makes its PMREM once). */
const rooms = new Map<string, Texture>();

/**
 * The centre pixel of film case `c` on WebGPURenderer: linear RGB read back, and as 8-bit sRGB; in
 * a uniform room of `room` (linear RGB from every direction: scene.environment) where one is given.
 */
async function nodePixel(
  c: FilmCase,
  kind: Kind,
  options: SpectralIridescenceOptions = {},
  room: readonly [number, number, number] | null = null,
): Promise<{ linear: number[]; codes: number[] }> {
  const material = materialOf(c, kind, options);
  if (kind !== 'three') await whenSpectralReady(material);
  const { scene, camera } = filmScene(c, material);
  if (room) {
    if (!rooms.has(room.join()))
      rooms.set(
        room.join(),
        environment(() => room),
      );
    scene.environment = rooms.get(room.join())!;
  }
  const pixel = await drawCentre(scene, camera);
  disposeAll(scene);
  return pixel;
}

/** Programs three has built in one piece (NodeBuilder.build, inside a render or compute) since the page loaded; compileAsync builds by buildAsync. */
let builtInPlace = 0;
// three's types leave out the builder's build(); it is NodeBuilder.prototype.build in r187.
const builder = NodeBuilder.prototype as unknown as { build: (this: unknown) => unknown };
const build = builder.build;
builder.build = function (this: unknown) {
  builtInPlace++;
  return build.call(this);
};

/**
 * The centre pixels of one node material of film case `c`, drawn once its film is ready and after
 * each change of its options in turn (8-bit codes), and the programs built in one piece after that.
 * All into one target, as a render loop draws (a program is built ahead for the target the
 * material was last drawn into, unless that has been disposed since). While a change's program may
 * be built ahead, a second object with the material is drawn too (its first draw: a render object
 * three makes then, which takes the material's program key then), and taken away again.
 */
async function changedPixels(
  c: FilmCase,
  changes: readonly SpectralIridescenceOptions[],
): Promise<{ codes: number[][]; builtInPlace: number }> {
  const material = materialOf(c, 'node', {});
  const { scene, camera, box } = filmScene(c, material);
  const target = floatTarget();
  await drawCentre(scene, camera, target);
  await whenSpectralReady(material);
  const codes = [(await drawCentre(scene, camera, target)).codes];
  const before = builtInPlace;
  for (const change of changes) {
    Object.assign(material, change);
    const second = box.clone();
    scene.add(second);
    await drawCentre(scene, camera, target);
    scene.remove(second);
    // as a user is told to: a change may need a program built off the frame first
    await whenSpectralReady(material);
    codes.push((await drawCentre(scene, camera, target)).codes);
  }
  target.dispose();
  disposeAll(scene);
  return { codes, builtInPlace: builtInPlace - before };
}

/**
 * The compute and render calls WebGPURenderer counts (renderer.info) over two frames of one node
 * material of film case `c`: the first builds what the material draws (its table in `table` mode).
 */
async function frameCalls(c: FilmCase, options: SpectralIridescenceOptions): Promise<{ compute: number; render: number }[]> {
  const { info } = renderer!;
  const { scene, camera } = filmScene(c, materialOf(c, 'node', options));
  const out = [];
  for (let frame = 0; frame < 2; frame++) {
    const before = { compute: info.compute.calls, render: info.render.calls };
    await drawCentre(scene, camera);
    out.push({ compute: info.compute.calls - before.compute, render: info.render.calls - before.render });
  }
  disposeAll(scene);
  return out;
}

/**
 * The centre pixel of film case `c` on WebGLRenderer, into a float target (linear), as 8-bit sRGB:
 * with the WebGL entry's film (`options`), or three's own iridescence (null).
 */
async function webglPixel(c: FilmCase, options: SpectralIridescenceOptions | null = {}): Promise<{ linear: number[]; codes: number[] }> {
  const { renderer: gl } = await import('./materialScene.ts');
  const { spectralIridescence: webglEntry, whenSpectralReady } = await import('../../../src/meshMaterial/spectralIridescence.ts');
  const material = filmMaterial(c, MeshPhysicalMaterial);
  const { scene, camera } = filmScene(c, options ? webglEntry(material, options) : material);
  // The WebGL entry's film is drawn once its drawing and its workers' answers are at hand (else three's, or the light before).
  if (options) await whenSpectralReady(material);
  const target = new WebGLRenderTarget(SIZE, SIZE, { type: FloatType });
  gl.setRenderTarget(target);
  gl.render(scene, camera);
  gl.setRenderTarget(null);
  const texels = new Float32Array(4);
  gl.readRenderTargetPixels(target, SIZE / 2, SIZE / 2, 1, 1, texels);
  target.dispose();
  disposeAll(scene);
  return { linear: [...texels.slice(0, 3)], codes: codes(texels) };
}

/** XYZ per case of every group through the node film (scripts/harness/nodeFilmProbe.ts). */
const nodeFilmXyz = (groups: readonly ParityGroup[], mode: NodeParityMode, quality: FilmQuality = DEFAULT_FILM_QUALITY) =>
  renderNodeFilmXyz(renderer!, groups, mode, quality);

window.webgpuHarness = { start, nodePixel, changedPixels, frameCalls, webglPixel, nodeFilmXyz };
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    webgpuHarness?: {
      start: typeof start;
      nodePixel: typeof nodePixel;
      changedPixels: typeof changedPixels;
      frameCalls: typeof frameCalls;
      webglPixel: typeof webglPixel;
      nodeFilmXyz: typeof nodeFilmXyz;
    };
  }
}

/**
 * The node figures' page (scripts/bench/nodeFigures.ts): three.js's WebGPURenderer on the backend
 * asked for, and on it the sphere's frame times with each material (nodeScene.ts), the WebGPU
 * entry's film over the error grids (scripts/harness/nodeFilmProbe.ts) and three.js's node
 * iridescence over them (the whole material: scripts/harness/materialGridScene.ts), and each option
 * change of a spectral material to its frame drawn, marked for a trace of its tasks.
 */
import { FloatType, NoToneMapping, RenderTarget } from 'three';
import { MeshPhysicalNodeMaterial, WebGPURenderer } from 'three/webgpu';
import type { FilmQuality } from '../../../src/settings/filmQuality.ts';
import { type DrawRow, gridMaterialParameters, gridXyz } from '../../harness/materialGridScene.ts';
import { type NodeParityMode, renderNodeFilmXyz } from '../../harness/nodeFilmProbe.ts';
import type { ParityGroup } from '../../harness/parityCase.ts';
import { median } from '../median.ts';
import { NODE_MATERIAL_NAMES, NODE_OPTION_CHANGES, type NodeBackend, type NodeMaterialName, changeMarks } from '../nodeMaterials.ts';
import { nodeScene } from './nodeScene.ts';

let renderer: WebGPURenderer | null = null;

/** Starts WebGPURenderer on `backend`; the backend it runs on (a browser without a WebGPU adapter falls back to WebGL2). */
async function start(backend: NodeBackend): Promise<NodeBackend> {
  void renderer?.dispose();
  renderer = new WebGPURenderer({ canvas: document.querySelector<HTMLCanvasElement>('#gpu')!, forceWebGL: backend === 'webgl' });
  renderer.toneMapping = NoToneMapping;
  await renderer.init();
  return (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend ? 'webgpu' : 'webgl';
}

/** A material's frames timed: their median (ms) and count. */
export interface NodeFrameTime {
  readonly medianMs: number;
  readonly count: number;
}

/**
 * The sphere's frames with each material, after each is ready: `frames` at most, one where the
 * first outlasts `budgetMs`. The materials take turns frame by frame so noise hits all alike.
 */
async function frameTimes(
  width: number,
  height: number,
  quality: FilmQuality,
  frames: number,
  budgetMs: number,
): Promise<Record<NodeMaterialName, NodeFrameTime>> {
  const s = nodeScene(renderer!, width, height, quality);
  try {
    for (const name of NODE_MATERIAL_NAMES) await s.drawReady(name);
    const times = Object.fromEntries(NODE_MATERIAL_NAMES.map((n) => [n, [] as number[]])) as Record<NodeMaterialName, number[]>;
    for (let i = 0; i < frames; i++)
      for (const name of NODE_MATERIAL_NAMES) {
        if (i > 0 && times[name][0]! > budgetMs) continue;
        const t0 = performance.now();
        await s.draw(name);
        times[name].push(performance.now() - t0);
      }
    return Object.fromEntries(NODE_MATERIAL_NAMES.map((n) => [n, { medianMs: median(times[n]), count: times[n].length }])) as Record<
      NodeMaterialName,
      NodeFrameTime
    >;
  } finally {
    s.dispose();
  }
}

/**
 * Each of NODE_OPTION_CHANGES in turn on the `table` sphere, once it is ready: drawn until the film
 * is ready, then once more; the change → that frame, ms. The change and its frame are marked
 * (changeMarks), so that a trace of the page tells its tasks.
 */
async function optionChanges(width: number, height: number, quality: FilmQuality): Promise<number[]> {
  const s = nodeScene(renderer!, width, height, quality);
  try {
    await s.drawReady('table');
    const toFrameMs: number[] = [];
    for (const [i, [, change]] of NODE_OPTION_CHANGES.entries()) {
      const [made, drawn] = changeMarks(i);
      const changedAt = performance.mark(made).startTime;
      Object.assign(s.materials.table, change);
      await s.drawReady('table');
      toFrameMs.push(performance.mark(drawn).startTime - changedAt);
      // The next change in a task of its own: a task is the change's whose window it overlaps.
      await new Promise((resolve) => setTimeout(resolve, 0));
    }
    return toFrameMs;
  } finally {
    s.dispose();
  }
}

/** XYZ per case of every group through the WebGPU entry's film in `mode`. */
const filmXyz = (groups: readonly ParityGroup[], mode: NodeParityMode, quality: FilmQuality) =>
  renderNodeFilmXyz(renderer!, groups, mode, quality);

const drawRow: DrawRow = async (scene, camera, width) => {
  const r = renderer!;
  const target = new RenderTarget(width, 1, { type: FloatType });
  r.setRenderTarget(target);
  r.render(scene, camera);
  r.setRenderTarget(null);
  const rgba = (await r.readRenderTargetPixelsAsync(target, 0, 0, width, 1)) as Float32Array;
  target.dispose();
  return rgba;
};

/** XYZ per case of every group through three.js's node iridescence: the whole material's pixels (materialGridScene.ts). */
async function threeGridXyz(groups: readonly ParityGroup[]): Promise<number[][][]> {
  const out: number[][][] = [];
  for (const g of groups) {
    const material = new MeshPhysicalNodeMaterial(gridMaterialParameters(g));
    out.push(await gridXyz(g, material, drawRow));
    material.dispose();
  }
  return out;
}

window.nodeBench = { start, frameTimes, optionChanges, filmXyz, threeGridXyz };
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    nodeBench?: {
      start: typeof start;
      frameTimes: typeof frameTimes;
      optionChanges: typeof optionChanges;
      filmXyz: typeof filmXyz;
      threeGridXyz: typeof threeGridXyz;
    };
  }
}

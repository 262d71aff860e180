/**
 * The WebGPU entry's figures on three.js's WebGPURenderer, on its WebGL2 backend (in the run's
 * browser) and on its WebGPU backend (in a launch of its own, which has WebGPU and no WebGL2:
 * scripts/chromium.ts): the frame of a sphere with three.js's node iridescence and with the
 * spectral film (`table`, `exact`) against the same material without iridescence, the film's ΔE00
 * over the error grids (and three.js's node iridescence's, the whole material's pixels), and the
 * main thread's tasks from each option change to its frame: the longest and those over
 * LONG_TASK_MS (from a trace of the page: each task's wall time and the thread's own time in it).
 */
import { type Browser, type Page, chromium } from '@playwright/test';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import type { FilmQuality } from '../../src/settings/filmQuality.ts';
import { webgpuLaunchOptions } from '../chromium.ts';
import type { ParityGroup } from '../harness/parityCase.ts';
import { loadOnBackend } from '../harness/webgpuAdapter.ts';
import { type GridError, filmsGridError, gridError } from './errorGrids.ts';
import { gpuApartUnavailable, withGpuApart } from './gpuApart.ts';
import {
  NODE_BACKENDS,
  NODE_GRID_MODES,
  NODE_OPTION_CHANGES,
  type NodeBackend,
  type NodeMaterialName,
  changeMarks,
} from './nodeMaterials.ts';
import { openPage } from './openPage.ts';
import type { NodeFrameTime } from './page/nodeBench.ts';
import { LONG_TASK_MS } from './panelChanges.ts';
import { TRACE_CATEGORIES, type TracedTask, tasksBetweenMarks } from './traceTasks.ts';

export interface NodeFiguresPlan {
  readonly width: number;
  readonly height: number;
  readonly frames: number;
  /** the spectral materials' and the error grids' film quality */
  readonly quality: FilmQuality;
  /**
   * Where the option changes are also made, besides at the frames' size with every core shared: a
   * small size, where a CPU rasteriser draws the sphere's frame well within LONG_TASK_MS (a task
   * that waits on the GPU process waits for the frame it is drawing), and the GPU process held to
   * a core of its own (gpuApart.ts), where the rasteriser's threads leave the page's core alone.
   */
  readonly changesAlsoAt: readonly ChangeSetting[];
}

/** How the option changes are made: the sphere's size, and whether the GPU process is held apart (gpuApart.ts). */
export interface ChangeSetting {
  readonly width: number;
  readonly height: number;
  readonly gpuApart: boolean;
}

/** One option change of NODE_OPTION_CHANGES: the main thread's tasks from the change to its frame drawn. */
export interface NodeChangeFigures {
  /** the longest task, ms */
  readonly longestMs: number;
  /** the main thread's own time in that task, ms (0 for none): the rest it waited or was not scheduled (traceTasks.ts) */
  readonly longestThreadMs: number;
  /** the longest time the main thread itself ran in any one task, ms: the page's own work, whatever it waited for */
  readonly mostThreadMs: number;
  /** tasks over LONG_TASK_MS */
  readonly over: number;
  /** the change → its frame drawn with the film ready, ms */
  readonly toFrameMs: number;
}

/** Every setting the option changes are made in: the frames' size with the cores shared, then the plan's changesAlsoAt. */
export const changeSettings = (how: NodeFiguresPlan): ChangeSetting[] => [
  { width: how.width, height: how.height, gpuApart: false },
  ...how.changesAlsoAt,
];

/** The option changes made in one setting. */
export interface NodeChangesAt extends ChangeSetting {
  /** per change of NODE_OPTION_CHANGES, in its order */
  readonly figures: NodeChangeFigures[];
}

export interface NodeBackendFigures {
  readonly backend: NodeBackend;
  /** the sphere's frames with each material: their median (ms) and count */
  readonly frames: Record<NodeMaterialName, NodeFrameTime>;
  /** per mode, the film's ΔE00 over each error grid */
  readonly gridErrors: Record<(typeof NODE_GRID_MODES)[number], GridError[]>;
  /**
   * three.js's node iridescence: the ΔE00 of the whole material's pixels over each error grid's
   * films thicker than 0 nm (three turns its film off at 0 nm and draws its own base there)
   */
  readonly threeGridErrors: GridError[];
  /** the option changes in each of changeSettings, in its order */
  readonly changes: NodeChangesAt[];
}

export interface NodeFigures extends NodeFiguresPlan {
  /** per backend of NODE_BACKENDS, in its order */
  readonly backends: NodeBackendFigures[];
}

/** Opens the page on `backend` (loadOnBackend: loaded again where a fresh browser's WebGPU found no adapter). */
async function openOn(browser: Browser, baseUrl: string, backend: NodeBackend, how: NodeFiguresPlan) {
  const page = await openPage(browser, { viewport: { width: how.width, height: how.height }, deviceScaleFactor: 1 });
  const started = await loadOnBackend(backend, async () => {
    await page.goto(`${baseUrl}/scripts/bench/page/nodeBench.html`);
    await page.waitForSelector('body[data-ready="yes"]');
    return page.evaluate((b) => window.nodeBench!.start(b), backend);
  });
  if (started) return page;
  await page.close();
  throw new Error(`WebGPURenderer found no ${backend} backend`);
}

/** Each of NODE_OPTION_CHANGES made on the page's sphere in `setting`: its tasks, from a trace of the page. */
async function optionChanges(browser: Browser, page: Page, setting: ChangeSetting, quality: FilmQuality): Promise<NodeChangeFigures[]> {
  const { width, height, gpuApart } = setting;
  await browser.startTracing(page, { categories: TRACE_CATEGORIES });
  const changed = () => page.evaluate(([w, h, q]) => window.nodeBench!.optionChanges(w, h, q), [width, height, quality] as const);
  const toFrameMs = await (gpuApart ? withGpuApart(browser, changed) : changed());
  const trace = (await browser.stopTracing()).toString();
  if (toFrameMs.length !== NODE_OPTION_CHANGES.length)
    throw new Error(`the page made ${toFrameMs.length} changes, not ${NODE_OPTION_CHANGES.length}`);
  const tasks = tasksBetweenMarks(
    trace,
    NODE_OPTION_CHANGES.map((_, i) => changeMarks(i)),
  );
  return tasks.map((all, i) => {
    const longest = all.reduce<TracedTask | null>((a, t) => (a && a.wallMs >= t.wallMs ? a : t), null);
    const over = all.filter((t) => t.wallMs > LONG_TASK_MS).length;
    const mostThreadMs = Math.max(0, ...all.map((t) => t.threadMs));
    return { longestMs: longest?.wallMs ?? 0, longestThreadMs: longest?.threadMs ?? 0, mostThreadMs, over, toFrameMs: toFrameMs[i]! };
  });
}

/** One backend's figures, in `browser`; a material whose first frame outlasts `how.frameBudgetMs` is timed once. */
async function backendFigures(
  browser: Browser,
  baseUrl: string,
  backend: NodeBackend,
  how: NodeFiguresPlan & { readonly frameBudgetMs: number },
  grids: readonly ParityGroup[],
  reference: readonly (readonly Xyz[])[],
): Promise<NodeBackendFigures> {
  const page = await openOn(browser, baseUrl, backend, how);
  try {
    const timed = [how.width, how.height, how.quality, how.frames, how.frameBudgetMs] as const;
    const frames = await page.evaluate(([w, h, q, n, budget]) => window.nodeBench!.frameTimes(w, h, q, n, budget), timed);
    const gridErrors = {} as NodeBackendFigures['gridErrors'];
    for (const mode of NODE_GRID_MODES) {
      const xyz = await page.evaluate(([g, m, q]) => window.nodeBench!.filmXyz(g, m, q), [grids, mode, how.quality] as const);
      gridErrors[mode] = grids.map((g, i) => gridError(g, reference[i]!, xyz[i]!));
    }
    const threes = await page.evaluate((g) => window.nodeBench!.threeGridXyz(g), grids);
    const threeGridErrors = grids.map((g, i) => filmsGridError(g, reference[i]!, threes[i]!));
    const changes: NodeChangesAt[] = [];
    for (const setting of changeSettings(how))
      changes.push({ ...setting, figures: await optionChanges(browser, page, setting, how.quality) });
    return { backend, frames, gridErrors, threeGridErrors, changes };
  } finally {
    await page.close();
  }
}

/** Both backends' figures: the WebGL2 backend's in `browser`, the WebGPU backend's in a browser launched for it and closed after. */
export async function nodeFigures(
  browser: Browser,
  baseUrl: string,
  how: NodeFiguresPlan & { readonly frameBudgetMs: number },
  grids: readonly ParityGroup[],
  reference: readonly (readonly Xyz[])[],
): Promise<NodeFigures> {
  const unavailable = gpuApartUnavailable();
  if (unavailable && how.changesAlsoAt.some((s) => s.gpuApart))
    console.warn(`node figures: no option changes with the GPU process apart: ${unavailable}`);
  const changesAlsoAt = how.changesAlsoAt.filter((s) => !(unavailable && s.gpuApart));
  const backends: NodeBackendFigures[] = [];
  for (const backend of NODE_BACKENDS) {
    const own = backend === 'webgpu' ? await chromium.launch(webgpuLaunchOptions()) : null;
    try {
      backends.push(await backendFigures(own ?? browser, baseUrl, backend, { ...how, changesAlsoAt }, grids, reference));
    } finally {
      await own?.close();
    }
  }
  const { width, height, frames, quality } = how;
  return { width, height, frames, quality, changesAlsoAt, backends };
}

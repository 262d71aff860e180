/**
 * The spectral material's benchmark figures: the example page's frame time with the spectral
 * film against the same scene with three.js's iridescence, and the gzipped JavaScript the
 * material adds to a three.js app that imports only it.
 */
import { mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { gzipSync } from 'node:zlib';
import type { Browser } from '@playwright/test';
import { build } from 'vite';
import type { View } from '../../src/pages/materialsScene.ts';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import type { ParityGroup } from '../harness/parityCase.ts';
import type { BenchPlan } from './benchPlan.ts';
import { type GridError, filmsGridError, gridError } from './errorGrids.ts';
import { openPage } from './openPage.ts';

/** The modes whose error the material's grids measure. */
const GRID_MODES = ['table', 'fourier'] as const;

export interface MaterialFigures {
  readonly width: number;
  readonly height: number;
  /** median frame (ms) of the example scene drawn with each material on both sides */
  readonly frameMs: Record<'three.js' | 'spectral', number>;
  readonly frames: number;
  /** gzipped JS of a minimal three.js app with MeshPhysicalMaterial's iridescence, and of the same app made spectral */
  readonly threeAppGzipBytes: number;
  readonly spectralAppGzipBytes: number;
  /**
   * per mode, the ΔE00 of the material's pixels over each error grid, and over its films thicker
   * than 0 (three turns the film off at 0 nm and draws its own base: Schlick's Fresnel)
   */
  readonly gridErrors: Record<(typeof GRID_MODES)[number], { all: GridError; films: GridError }[]>;
}

/** The error grids drawn by the whole material (scripts/harness/materialGrid.ts), against the reference. */
async function gridErrors(
  browser: Browser,
  baseUrl: string,
  grids: readonly ParityGroup[],
  reference: readonly (readonly Xyz[])[],
): Promise<MaterialFigures['gridErrors']> {
  const page = await openPage(browser);
  try {
    await page.goto(`${baseUrl}/scripts/harness/materialGrid.html`);
    await page.waitForSelector('body[data-ready="yes"]');
    const errors = {} as MaterialFigures['gridErrors'];
    for (const mode of GRID_MODES) {
      errors[mode] = [];
      for (const [i, g] of grids.entries()) {
        const xyz = await page.evaluate(([g, mode]) => window.materialGridXyz!(g, mode), [g, mode] as const);
        errors[mode].push({ all: gridError(g, reference[i]!, xyz), films: filmsGridError(g, reference[i]!, xyz) });
      }
    }
    return errors;
  } finally {
    await page.close();
  }
}

type FrameTimesPlan = BenchPlan['materials'];

/** Median frame times of the example page (materials.html), the two views alternating frame by frame so noise hits both alike. */
async function frameTimes(browser: Browser, baseUrl: string, how: FrameTimesPlan): Promise<MaterialFigures['frameMs']> {
  const page = await openPage(browser, { viewport: { width: how.width, height: how.height }, deviceScaleFactor: 1 });
  try {
    await page.goto(`${baseUrl}/materials.html`);
    await page.waitForSelector('body[data-frames]');
    return await page.evaluate((frames) => {
      const views: View[] = ['three.js', 'spectral'];
      const times: Record<string, number[]> = { 'three.js': [], spectral: [] };
      for (const v of views) for (let i = 0; i < 3; i++) window.materialsPage!.draw(v); // warm-up
      for (let i = 0; i < frames; i++)
        for (const v of views) {
          const t0 = performance.now();
          window.materialsPage!.draw(v); // ends with a 1-pixel read: the frame is done
          times[v]!.push(performance.now() - t0);
        }
      // (No named functions in here: tsx would wrap them in a helper the page does not have.)
      for (const v of views) times[v]!.sort((x, y) => x - y);
      return { 'three.js': times['three.js']![frames >> 1]!, spectral: times.spectral![frames >> 1]! };
    }, how.frames);
  } finally {
    await page.close();
  }
}

/** A minimal three.js app: one iridescent MeshPhysicalMaterial drawn once; `spectral` adds the one call that makes it spectral. */
const appSource = (spectral: boolean) => `
import { Mesh, MeshPhysicalMaterial, PerspectiveCamera, Scene, TorusKnotGeometry, WebGLRenderer } from 'three';
${spectral ? `import { spectralIridescence } from ${JSON.stringify(resolve('src/packageEntries/material.ts'))};` : ''}
const material = new MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.33 });
${spectral ? 'spectralIridescence(material);' : ''}
const scene = new Scene();
scene.add(new Mesh(new TorusKnotGeometry(), material));
new WebGLRenderer().render(scene, new PerspectiveCamera());
`;

async function appGzipBytes(spectral: boolean): Promise<number> {
  const root = resolve('.scratch', `bench-material-app-${spectral ? 'spectral' : 'three'}`);
  rmSync(root, { recursive: true, force: true });
  mkdirSync(root, { recursive: true });
  writeFileSync(join(root, 'main.js'), appSource(spectral));
  const outDir = join(root, 'dist');
  await build({
    root,
    configFile: false,
    logLevel: 'silent',
    build: { outDir, chunkSizeWarningLimit: 2000, rolldownOptions: { input: join(root, 'main.js') } },
  });
  const js = (dir: string): string[] =>
    readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
      e.isDirectory() ? js(join(dir, e.name)) : e.name.endsWith('.js') ? [join(dir, e.name)] : [],
    );
  const bytes = js(outDir).reduce((sum, f) => sum + gzipSync(readFileSync(f), { level: 9 }).length, 0);
  rmSync(root, { recursive: true, force: true });
  return bytes;
}

export async function materialFigures(
  browser: Browser,
  baseUrl: string,
  how: FrameTimesPlan,
  grids: readonly ParityGroup[],
  reference: readonly (readonly Xyz[])[],
): Promise<MaterialFigures> {
  return {
    gridErrors: await gridErrors(browser, baseUrl, grids, reference),
    width: how.width,
    height: how.height,
    frameMs: await frameTimes(browser, baseUrl, how),
    frames: how.frames,
    threeAppGzipBytes: await appGzipBytes(false),
    spectralAppGzipBytes: await appGzipBytes(true),
  };
}

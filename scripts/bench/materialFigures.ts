/**
 * The spectral material's benchmark figures: the example page's frame time with the spectral
 * film against the same scene with three.js's iridescence, and the gzipped JavaScript each
 * material entry adds to three's minimal app on its renderer (entryBytes.ts).
 */
import type { Browser } from '@playwright/test';
import type { View } from '../../src/pages/materialsScene.ts';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import type { ParityGroup } from '../harness/parityCase.ts';
import type { BenchPlan } from './benchPlan.ts';
import { type EntryBytes, materialEntryBytes } from './entryBytes.ts';
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
  /** per material entry, three's minimal app on its renderer and the same app made spectral: eager and emitted bytes, gzipped */
  readonly entryBytes: readonly EntryBytes[];
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
    entryBytes: await materialEntryBytes(),
  };
}

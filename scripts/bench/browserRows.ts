/** Runs the benchmark rows in headless Chromium, one fresh page (and WebGL context) per row. */
import { smokeQuality } from './benchPlan.ts';
import type { Browser } from '@playwright/test';
import type { ParityGroup } from '../harness/parityCase.ts';
import type { BenchPlan } from './benchPlan.ts';
import type { BenchRowResult } from './benchRow.ts';
import type { BenchRow } from './rows.ts';
import { openPage } from './openPage.ts';

/** One row in a fresh page; `grids` empty where the row measures no error (then `xyz` is empty). */
export async function runRow(
  browser: Browser,
  baseUrl: string,
  plan: BenchPlan,
  row: BenchRow,
  grids: readonly ParityGroup[],
): Promise<BenchRowResult> {
  const page = await openPage(browser, { viewport: { width: 640, height: 360 } });
  try {
    await page.goto(`${baseUrl}/scripts/bench/page/bench.html`);
    await page.waitForSelector('body[data-ready="yes"]');
    return await page.evaluate((spec) => window.benchRow!(spec), {
      kind: row.kind,
      reflections: row.reflections ?? true,
      timesChanges: row.timesChanges ?? true,
      settings: row.settings,
      quality: plan.smoke ? smokeQuality(row.quality) : row.quality,
      sizes: plan.sizes,
      frames: plan.frames,
      frameBudgetMs: plan.frameBudgetMs,
      changeRepeats: plan.changeRepeats,
      changesBack: plan.changesBack,
      grids,
    });
  } finally {
    await page.close();
  }
}

/** Loads the page once so the dev server has transformed every module before the first-frame times. */
export async function warmUp(browser: Browser, baseUrl: string): Promise<void> {
  const page = await openPage(browser);
  await page.goto(`${baseUrl}/scripts/bench/page/bench.html`);
  await page.waitForSelector('body[data-ready="yes"]');
  await page.close();
}

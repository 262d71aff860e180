/**
 * Runs the benchmark rows in headless Chromium: one fresh page (and WebGL context) per row, or
 * (`plan.pagePerLane`) one page per lane, each of the lane's rows run in it in turn; and the
 * flowing film's GPU simulation in a page of its own.
 */
import { smokeQuality } from './benchPlan.ts';
import type { Browser, Page } from '@playwright/test';
import type { ParityGroup } from '../harness/parityCase.ts';
import type { BenchPlan } from './benchPlan.ts';
import type { BenchRowResult } from './benchRow.ts';
import type { BenchRow } from './rows.ts';
import type { FlowSpeedPlan, GpuSimulationSpeed } from './flowSpeed.ts';
import { openPage } from './openPage.ts';

const BENCH_PAGE = '/scripts/bench/page/bench.html';

async function openBenchPage(browser: Browser, baseUrl: string): Promise<Page> {
  const page = await openPage(browser, { viewport: { width: 640, height: 360 } });
  await page.goto(`${baseUrl}${BENCH_PAGE}`);
  await page.waitForSelector('body[data-ready="yes"]');
  return page;
}

/** The rows of one lane (the tasks that run one after another): where each runs, by the plan. */
export class RowLane {
  /** The lane's page between its rows, where the plan keeps one (opened at the lane's first row). */
  private page: Page | null = null;

  constructor(
    private readonly browser: Browser,
    private readonly baseUrl: string,
    private readonly plan: BenchPlan,
  ) {}

  /** One row; `grids` empty where the row measures no error (then `xyz` is empty). */
  async run(row: BenchRow, grids: readonly ParityGroup[]): Promise<BenchRowResult> {
    const page = this.page ?? (await openBenchPage(this.browser, this.baseUrl));
    this.page = null;
    try {
      const result = await page.evaluate((spec) => window.benchRow!(spec), {
        kind: row.kind,
        earlierModel: row.earlierModel ?? null,
        takesTurnsWith: row.takesTurnsWith ?? null,
        timesChanges: row.timesChanges ?? true,
        settings: row.settings,
        quality: this.plan.smoke ? smokeQuality(row.quality) : row.quality,
        sizes: this.plan.sizes,
        frames: this.plan.frames,
        frameBudgetMs: this.plan.frameBudgetMs,
        changeRepeats: this.plan.changeRepeats,
        changesBack: this.plan.changesBack,
        grids,
      });
      // Kept for the lane's next row only after a row that ran to its end: one that threw may have left the page in any state.
      if (this.plan.pagePerLane) this.page = page;
      return result;
    } finally {
      if (this.page !== page) await page.close();
    }
  }

  /** Closes the lane's page, if it holds one. */
  async close(): Promise<void> {
    await this.page?.close();
    this.page = null;
  }
}

/** Loads the page once so the dev server has transformed every module before the first-frame times. */
export async function warmUp(browser: Browser, baseUrl: string): Promise<void> {
  await (await openBenchPage(browser, baseUrl)).close();
}

/** The flowing film's GPU simulation timed in a fresh benchmark page (page/gpuFlowSpeed.ts). */
export async function gpuFlowSpeedInPage(browser: Browser, baseUrl: string, plan: FlowSpeedPlan): Promise<GpuSimulationSpeed[]> {
  const page = await openBenchPage(browser, baseUrl);
  try {
    return await page.evaluate((p) => window.benchFlowSpeed!(p), plan);
  } finally {
    await page.close();
  }
}

import type { Browser } from '@playwright/test';
import { describe, expect, it } from 'vitest';
import { FULL_PLAN, SMOKE_PLAN } from '../../../scripts/bench/benchPlan.ts';
import { RowLane } from '../../../scripts/bench/browserRows.ts';
import type { BenchRowResult } from '../../../scripts/bench/benchRow.ts';
import { ROWS } from '../../../scripts/bench/rows.ts';

const RESULT: BenchRowResult = {
  firstFrameMs: 1,
  tableBuildMs: null,
  rebuildsWhileAnimating: 0,
  frames: [],
  changeToFrameMs: [],
  turns: null,
  xyz: [],
};

/** A browser whose pages run rows without drawing: each page's rows in order, `failing` rows throwing. */
function fakeBrowser(failing: ReadonlySet<number> = new Set()) {
  const pages: { rows: number; closed: boolean }[] = [];
  let rowsRun = 0;
  const browser = {
    newPage: () => {
      const page = { rows: 0, closed: false };
      pages.push(page);
      return Promise.resolve({
        setDefaultTimeout: () => {},
        goto: () => Promise.resolve(null),
        waitForSelector: () => Promise.resolve(null),
        evaluate: () => {
          page.rows++;
          return failing.has(rowsRun++) ? Promise.reject(new Error('the row threw')) : Promise.resolve(RESULT);
        },
        close: () => {
          page.closed = true;
          return Promise.resolve();
        },
      });
    },
  };
  return { browser: browser as unknown as Browser, pages };
}

describe('a lane of bench rows', () => {
  it('opens a fresh page per row where the plan says so, and closes each', async () => {
    const { browser, pages } = fakeBrowser();
    const lane = new RowLane(browser, 'http://bench', FULL_PLAN);
    for (const row of ROWS.slice(0, 3)) await lane.run(row, []);
    expect(pages).toEqual(Array.from({ length: 3 }, () => ({ rows: 1, closed: true })));
  });

  it('runs every row in one page where the plan keeps one per lane, closed with the lane', async () => {
    const { browser, pages } = fakeBrowser();
    const lane = new RowLane(browser, 'http://bench', SMOKE_PLAN);
    for (const row of ROWS.slice(0, 3)) await lane.run(row, []);
    expect(pages).toEqual([{ rows: 3, closed: false }]);
    await lane.close();
    expect(pages).toEqual([{ rows: 3, closed: true }]);
  });

  it('drops the page a row threw in: the next row opens a fresh one', async () => {
    const { browser, pages } = fakeBrowser(new Set([1]));
    const lane = new RowLane(browser, 'http://bench', SMOKE_PLAN);
    await lane.run(ROWS[0]!, []);
    await expect(lane.run(ROWS[1]!, [])).rejects.toThrow('the row threw');
    await lane.run(ROWS[2]!, []);
    await lane.close();
    expect(pages).toEqual([
      { rows: 2, closed: true },
      { rows: 1, closed: true },
    ]);
  });
});

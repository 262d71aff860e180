/**
 * The built demo page (vite preview of dist): its first frame, and how many frames it draws and
 * tables it builds when nothing moves, while the swirl animates, and while hidden.
 */
import type { Browser, Page } from '@playwright/test';

export interface DemoPageFigures {
  /** navigation start to the first frame drawn and read back (an upper bound: includes Playwright's polling) */
  readonly firstFrameMs: number;
  /** frames drawn / tables built in one second */
  readonly still: FrameCounts;
  readonly animating: FrameCounts;
  readonly canvasHidden: FrameCounts;
  readonly pageHidden: FrameCounts;
}
export interface FrameCounts {
  readonly frames: number;
  readonly tableBuilds: number;
}

const WINDOW_MS = 1000;

async function countOneSecond(page: Page): Promise<FrameCounts> {
  return page.evaluate(async (ms) => {
    const view = (window as unknown as { bubbleView: { render(): void; table: { builds: number } } }).bubbleView;
    let frames = 0;
    const render = view.render.bind(view);
    view.render = () => {
      frames++;
      render();
    };
    const builds = view.table.builds;
    await new Promise((r) => setTimeout(r, ms));
    view.render = render;
    return { frames, tableBuilds: view.table.builds - builds };
  }, WINDOW_MS);
}

async function open(browser: Browser, url: string): Promise<{ page: Page; firstFrameMs: number }> {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await page.goto(url);
  await page.waitForSelector('body[data-frames="ready"]');
  const firstFrameMs = await page.evaluate(() => {
    const gl = document.querySelector<HTMLCanvasElement>('#bubble')!.getContext('webgl2')!;
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return performance.now();
  });
  return { page, firstFrameMs };
}

export async function demoPageFigures(browser: Browser, baseUrl: string): Promise<DemoPageFigures> {
  const still = await open(browser, `${baseUrl}/?animate=0`);
  const stillCounts = await countOneSecond(still.page);
  await still.page.close();
  const { page, firstFrameMs } = await open(browser, `${baseUrl}/`);
  const animating = await countOneSecond(page);
  await page.evaluate(() => (document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = 'none'));
  const canvasHidden = await countOneSecond(page);
  await page.evaluate(() => {
    document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = '';
    Object.defineProperty(document, 'hidden', { value: true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  const pageHidden = await countOneSecond(page);
  await page.close();
  return { firstFrameMs, still: stillCounts, animating, canvasHidden, pageHidden };
}

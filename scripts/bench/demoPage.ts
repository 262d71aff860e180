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
  /** per change of PANEL_CHANGES: panel input → the next frame drawn (plots included) and read back, median ms */
  readonly panelChangeMs: readonly number[];
  /** the default view's median frame time while the swirl animates, for the ratio */
  readonly frameMs: number;
}

/** Panel changes as a user makes them: [controller name, value, value back]. */
export const PANEL_CHANGES = [
  ['n film', '1.4', '1.33'],
  ['illuminant', 'D93', 'D65'],
  ['polarization', 's', 'unpolarized'],
  ['range (nm)', '1200', '800'],
] as const;

/**
 * Each change through the lil-gui panel (a number box's input event, or a list's change event),
 * three times there and back, timed from the event to the end of the next frame the app draws
 * (renderNow: the table if due, the bubble, the plots), synced by a 1-pixel read.
 */
async function panelChanges(page: Page): Promise<{ panelChangeMs: number[]; frameMs: number }> {
  return page.evaluate(async (changes) => {
    type App = { renderNow(): void };
    const app = (window as unknown as { bubbleApp: App }).bubbleApp;
    const gl = document.querySelector<HTMLCanvasElement>('#bubble')!.getContext('webgl2')!;
    const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;
    const nextFrame = (act: () => void) =>
      new Promise<number>((resolve) => {
        const draw = app.renderNow;
        const started = performance.now();
        app.renderNow = () => {
          draw.call(app);
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
          app.renderNow = draw;
          resolve(performance.now() - started);
        };
        act();
      });
    const controller = (name: string) =>
      [...document.querySelectorAll<HTMLElement>('.lil-controller')].find((c) => c.querySelector('.lil-name')!.textContent === name)!;
    const set = (name: string, value: string) => () => {
      const c = controller(name);
      const select = c.querySelector('select');
      if (select) {
        select.value = value;
        select.dispatchEvent(new Event('change', { bubbles: true }));
      } else {
        const input = c.querySelector('input')!;
        input.value = value;
        input.dispatchEvent(new Event('input', { bubbles: true }));
      }
    };
    const frames: number[] = [];
    for (let i = 0; i < 9; i++) frames.push(await nextFrame(() => {}));
    const panelChangeMs: number[] = [];
    for (const [name, value, back] of changes) {
      const times: number[] = [];
      for (let i = 0; i < 3; i++) {
        times.push(await nextFrame(set(name, value)));
        times.push(await nextFrame(set(name, back)));
      }
      panelChangeMs.push(median(times));
    }
    return { panelChangeMs, frameMs: median(frames) };
  }, PANEL_CHANGES);
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
  // tsx names the functions it compiles with a helper (__name) that pages evaluated from here lack.
  await page.addInitScript({ content: 'window.__name = (f) => f;' });
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
  const { panelChangeMs, frameMs } = await panelChanges(page);
  await page.evaluate(() => (document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = 'none'));
  const canvasHidden = await countOneSecond(page);
  await page.evaluate(() => {
    document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = '';
    Object.defineProperty(document, 'hidden', { value: true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  const pageHidden = await countOneSecond(page);
  await page.close();
  return { firstFrameMs, still: stillCounts, animating, canvasHidden, pageHidden, panelChangeMs, frameMs };
}

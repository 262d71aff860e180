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
  /** per change of PANEL_CHANGES: panel input → the next frame drawn and read back, median ms */
  readonly panelChangeMs: readonly number[];
  /** … → the first frame that shows the change in full (not from a coarse table), median ms */
  readonly panelChangeFullMs: readonly number[];
  /** the default view's median frame time while the swirl animates, for the ratio */
  readonly frameMs: number;
}

/** Panel changes as a user makes them: [controller name, value, value back]. */
export const PANEL_CHANGES = [
  ['n film', '1.4', '1.33'],
  ['film material', 'water', 'constant'],
  ['illuminant', 'D93', 'D65'],
  ['polarization', 's', 'unpolarized'],
  ['range (nm)', '1200', '800'],
] as const;

/**
 * Each change through the lil-gui panel (a number box's input event, or a list's change event),
 * three times there and back, timed from the event to the end of the next frame the app draws
 * (the table if due, coarse first, the bubble), synced by a 1-pixel read; and to the end of the
 * first frame drawn in full, plots included.
 */
async function panelChanges(page: Page): Promise<{ panelChangeMs: number[]; panelChangeFullMs: number[]; frameMs: number }> {
  return page.evaluate(async (changes) => {
    type View = { render(quick?: boolean): void; coarse: boolean };
    const view = (window as unknown as { bubbleView: View }).bubbleView;
    const gl = document.querySelector<HTMLCanvasElement>('#bubble')!.getContext('webgl2')!;
    const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;
    const afterFrame = () => new Promise((resolve) => setTimeout(resolve, 0)); // the plots follow a complete frame in the same task
    /** [ms to the next frame, ms to the first complete frame] after `act`. */
    const nextFrames = (act: () => void) =>
      new Promise<[number, number]>((resolve) => {
        // eslint-disable-next-line @typescript-eslint/unbound-method -- wrapped below and called with .call(this)
        const render = view.render;
        const started = performance.now();
        let first = 0;
        view.render = (quick?: boolean) => {
          render.call(view, quick);
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
          first ||= performance.now() - started;
          if (view.coarse) return;
          view.render = render;
          void afterFrame().then(() => resolve([first, performance.now() - started]));
        };
        act();
      });
    const nextFrame = async (act: () => void) => (await nextFrames(act))[0];
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
    const panelChangeFullMs: number[] = [];
    for (const [name, value, back] of changes) {
      const times: [number, number][] = [];
      for (let i = 0; i < 3; i++) {
        times.push(await nextFrames(set(name, value)));
        times.push(await nextFrames(set(name, back)));
      }
      panelChangeMs.push(median(times.map((t) => t[0])));
      panelChangeFullMs.push(median(times.map((t) => t[1])));
    }
    return { panelChangeMs, panelChangeFullMs, frameMs: median(frames) };
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
  const { panelChangeMs, panelChangeFullMs, frameMs } = await panelChanges(page);
  await page.evaluate(() => (document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = 'none'));
  const canvasHidden = await countOneSecond(page);
  await page.evaluate(() => {
    document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = '';
    Object.defineProperty(document, 'hidden', { value: true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  const pageHidden = await countOneSecond(page);
  await page.close();
  return { firstFrameMs, still: stillCounts, animating, canvasHidden, pageHidden, panelChangeMs, panelChangeFullMs, frameMs };
}

/**
 * The render command's browser session: the demo served by Vite's dev server on a free loopback
 * port, one headless Chromium, and per view a window of the view's size in which the demo page is
 * opened at the view's URL, waited on until its frame is drawn, and captured as a PNG.
 */
import { fileURLToPath } from 'node:url';
import { type Browser, type Page, chromium } from '@playwright/test';
import { createServer } from 'vite';
import type { RenderView } from '../../src/cli/renderOptions.ts';
import { type ChromiumLaunchOptions, checkedRenderer } from '../chromium.ts';
import { FRAME_DRAWN, PANEL, PLOT_PANEL, PLOTS, PLOTS_BOX, PLOTS_DRAWN } from './demoPage.ts';

/** The repository, whose index.html is the demo. */
const ROOT = fileURLToPath(new URL('../..', import.meta.url));

/**
 * How long any one step of a view (opening the page, its first frame, the capture) may take:
 * ~3 s in all here on SwiftShader, so this leaves room for a machine many times slower; a view
 * that takes longer fails the command (exit 1).
 */
const STEP_TIMEOUT_MS = 300_000;

/** A rendered view: its PNG, the PNG's size in pixels, and how long it took (page opened → PNG captured). */
export interface RenderedView {
  readonly png: Buffer;
  readonly width: number;
  readonly height: number;
  readonly ms: number;
}

/**
 * Renders `views` in order in one browser launch, handing each PNG to `take` as soon as it is
 * captured (before the next view is opened). Everything is closed on return and on error.
 */
export async function renderViews(
  views: readonly RenderView[],
  launch: ChromiumLaunchOptions,
  take: (view: RenderView, rendered: RenderedView) => void,
): Promise<void> {
  if (views.length === 0) return;
  await withDemo(launch, async (browser, base) => {
    for (const view of views) take(view, await renderView(browser, base, view));
  });
}

/**
 * Runs `use` with the demo served at `base` and one launched (and checked) Chromium; everything
 * is closed on return and on error.
 */
export async function withDemo<T>(launch: ChromiumLaunchOptions, use: (browser: Browser, base: string) => Promise<T>): Promise<T> {
  const server = await createServer({
    root: ROOT,
    logLevel: 'silent',
    server: { host: '127.0.0.1', port: 0, strictPort: true, hmr: false, watch: null },
  });
  try {
    await server.listen();
    const address = server.httpServer?.address();
    if (!address || typeof address === 'string') throw new Error('the demo server has no port');
    const browser = await chromium.launch(launch);
    try {
      // A picture from another backend than TFC_GL names, or a 2-D canvas, would not be the one asked for.
      await checkedRenderer(browser);
      return await use(browser, `http://127.0.0.1:${address.port}`);
    } finally {
      await browser.close();
    }
  } finally {
    await server.close();
  }
}

/** A page in a window of `view`'s size, each step allowed STEP_TIMEOUT_MS; `use` runs with it, and its context is closed after. */
export async function withViewPage<T>(browser: Browser, view: RenderView, use: (page: Page) => Promise<T>): Promise<T> {
  const context = await browser.newContext({ viewport: { width: view.widthPx, height: view.heightPx }, deviceScaleFactor: view.scale });
  context.setDefaultTimeout(STEP_TIMEOUT_MS);
  context.setDefaultNavigationTimeout(STEP_TIMEOUT_MS);
  try {
    return await use(await context.newPage());
  } finally {
    await context.close();
  }
}

/** The window as a PNG once `shown` resolves (a page error meanwhile fails it). */
async function captureWhenShown(page: Page, shown: () => Promise<void>): Promise<Buffer> {
  let onError: (error: Error) => void = () => undefined;
  const failed = new Promise<never>((_, reject) => {
    onError = (e) => reject(new Error(`the demo page failed: ${e.message}`));
  });
  page.on('pageerror', onError);
  try {
    await Promise.race([shown(), failed]);
  } finally {
    page.off('pageerror', onError);
  }
  return page.screenshot({ type: 'png', animations: 'disabled', caret: 'hide' });
}

/** The window as a PNG once the page shows `view` (a page error fails it). */
export const capture = (page: Page, base: string, view: RenderView): Promise<Buffer> =>
  captureWhenShown(page, () => showView(page, base, view));

/**
 * The window as a PNG once the page shown by `capture` shows its view at another film time: the
 * time given to the page's app in place, and waited on until a frame at it is drawn in full (a
 * page error fails it).
 */
export const captureAtTime = (page: Page, timeSeconds: number): Promise<Buffer> =>
  captureWhenShown(page, async () => {
    await page.evaluate((t) => {
      type App = { current: object; set(s: object): void };
      const app = (window as unknown as { bubbleApp: App }).bubbleApp;
      delete document.body.dataset.frames;
      app.set({ ...app.current, timeSeconds: t });
    }, timeSeconds);
    await page.waitForSelector(FRAME_DRAWN, { state: 'attached' });
  });

async function renderView(browser: Browser, base: string, view: RenderView): Promise<RenderedView> {
  const started = performance.now();
  const png = await withViewPage(browser, view, (page) => capture(page, base, view));
  // The size, from the PNG's IHDR chunk (its first, right after the 8-byte signature).
  return { png, width: png.readUInt32BE(16), height: png.readUInt32BE(20), ms: Math.round(performance.now() - started) };
}

/** Opens the demo at the view and waits for its frame; the panel hidden, and the plots unless asked for (their drawer opened). */
async function showView(page: Page, base: string, view: RenderView): Promise<void> {
  await page.goto(`${base}/${view.query ? `?${view.query}` : ''}`);
  await page.waitForSelector(FRAME_DRAWN, { state: 'attached' });
  await page.addStyleTag({ content: `${view.plots ? PANEL : `${PANEL}, ${PLOTS}`} { display: none !important; }` });
  if (!view.plots) return;
  // A small window starts with the plots' drawer closed: open it, and wait for the plots drawn into it.
  await page.evaluate(
    ([box, plots]) => {
      const drawer = document.querySelector<HTMLDetailsElement>(box);
      if (!drawer || drawer.open) return;
      document.querySelector(plots)?.removeAttribute('data-probe');
      drawer.open = true;
    },
    [PLOTS_BOX, PLOT_PANEL] as const,
  );
  await page.waitForSelector(PLOTS_DRAWN, { state: 'attached' });
}

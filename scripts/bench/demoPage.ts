/**
 * The built demo page (vite preview of dist): its first frame, and how many frames it draws and
 * tables it builds when nothing moves, while the swirl animates, and while hidden; what its panel
 * changes cost (panelChanges.ts).
 */
import type { Browser, Page } from '@playwright/test';
import { FRAME_MARKS } from '../../src/pages/frameMarks.ts';
import type { BenchPlan } from './benchPlan.ts';
import { openPage } from './openPage.ts';
import { type PanelChangeFigures, panelChanges } from './panelChanges.ts';

type DemoPlan = BenchPlan['demo'];

export interface DemoPageFigures {
  /** navigation start to the first frame drawn (its pixels read back as the page marks it: FRAME_DRAWN_SCRIPT) */
  readonly firstFrameMs: number;
  /** … to the first frame drawn in full (not from a coarse table) */
  readonly firstCompleteFrameMs: number;
  /** frames drawn / tables built in one second */
  readonly still: FrameCounts;
  readonly animating: FrameCounts;
  readonly canvasHidden: FrameCounts;
  readonly pageHidden: FrameCounts;
  /** per change of PANEL_CHANGES, what it cost the page, counts that do not depend on the rasteriser's speed */
  readonly panel: readonly PanelChangeFigures[];
  /** whether the GPU compiles in parallel (KHR_parallel_shader_compile): where it does, a change must leave no long task */
  readonly parallelCompile: boolean;
}

/**
 * From before any script runs: a count of the programs the page links (every WebGL2 context's
 * linkProgram), and every long task the main thread runs (PerformanceObserver, `longtask`).
 */
const COUNTERS_SCRIPT = `
window.__name = (f) => f;
window.programsLinked = 0;
const link = WebGL2RenderingContext.prototype.linkProgram;
WebGL2RenderingContext.prototype.linkProgram = function (program) { window.programsLinked++; return link.call(this, program); };
window.longTasks = [];
new PerformanceObserver((list) => { for (const e of list.getEntries()) window.longTasks.push([e.startTime, e.duration]); }).observe({ type: 'longtask', buffered: true });
`;

/** The demo page's canvas (index.html), whose WebGL2 context draws the bubble. */
const BUBBLE_CANVAS_ID = 'bubble';

/**
 * From before any script runs: when each of the page's frame marks (FRAME_MARKS) is set, the time
 * that frame's pixels are drawn, `framesDrawn[mark]`: one pixel of the drawing buffer read back
 * right then, which waits for the GPU to finish the frame (its programs' link included). Not the
 * next animation frame's time: that waits for whatever the page's main thread does next (the
 * default view makes its film's simulation in the frame after its first), while the compositor
 * shows the frame already drawn.
 */
const FRAME_DRAWN_SCRIPT = `
window.framesDrawn = {};
const getContext = HTMLCanvasElement.prototype.getContext;
HTMLCanvasElement.prototype.getContext = function (...args) {
  const context = getContext.apply(this, args);
  if (this.id === ${JSON.stringify(BUBBLE_CANVAS_ID)} && context instanceof WebGL2RenderingContext) window.bubbleGl = context;
  return context;
};
const mark = performance.mark.bind(performance);
const frameMarks = ${JSON.stringify(Object.values(FRAME_MARKS))};
performance.mark = function (name, options) {
  const entry = mark(name, options);
  const gl = window.bubbleGl;
  if (gl && frameMarks.includes(name) && !(name in window.framesDrawn)) {
    const read = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    const pack = gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, read);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pack);
    window.framesDrawn[name] = performance.now();
  }
  return entry;
};
`;

export interface FrameCounts {
  readonly frames: number;
  readonly tableBuilds: number;
}

const WINDOW_MS = 1000;

async function countOneSecond(page: Page): Promise<FrameCounts> {
  return page.evaluate(async (ms) => {
    type Table = { readonly coarse: boolean; update(...args: unknown[]): boolean };
    const view = (window as unknown as { bubbleView: { render(pace?: 'paced' | 'complete'): unknown; table: Table } }).bubbleView;
    let frames = 0;
    const render = view.render.bind(view);
    // The frame's report goes back to the app, whose frame loop follows it.
    view.render = (pace?: 'paced' | 'complete') => {
      frames++;
      return render(pace);
    };
    // A full table shown: an update that changed what the table binds and left no coarse one.
    let tableBuilds = 0;
    const table = view.table;
    const update = table.update.bind(table);
    table.update = (...args) => {
      const changed = update(...args);
      if (changed && !table.coarse) tableBuilds++;
      return changed;
    };
    await new Promise((r) => setTimeout(r, ms));
    view.render = render;
    Reflect.deleteProperty(table, 'update');
    return { frames, tableBuilds };
  }, WINDOW_MS);
}

/**
 * The built demo at `url` in a fresh page of the plan's size (each animation frame running
 * `eachFrame`), once its first frame in full is drawn: the page and when its first frame, and its
 * first in full, were drawn (ms from navigation, FRAME_DRAWN_SCRIPT). Unless `readBack`: when the
 * page marked them, nothing read back, for a page whose frames are measured after (a read back
 * waits for the GPU within a frame, and would lengthen it).
 */
export async function openDemo(
  browser: Browser,
  url: string,
  how: Pick<DemoPlan, 'width' | 'height'>,
  /** what each animation frame also runs, from the first (JavaScript source, a statement; `t` is the frame's time) */
  eachFrame = '',
  readBack = true,
): Promise<{ page: Page; firstFrameMs: number; firstCompleteFrameMs: number }> {
  const page = await openPage(browser, { viewport: { width: how.width, height: how.height } });
  // tsx names the functions it compiles with a helper (__name) that pages evaluated from here lack.
  // From before any script runs, the timestamp of every animation frame shown.
  await page.addInitScript({
    content: `${COUNTERS_SCRIPT}\n${readBack ? FRAME_DRAWN_SCRIPT : ''}\nwindow.shownFrames = []; (function tick(t) { window.shownFrames.push(t); ${eachFrame} requestAnimationFrame(tick); })(0);`,
  });
  await page.goto(url);
  await page.waitForSelector('body[data-frames="ready"]');
  const [firstFrameMs, firstCompleteFrameMs] = await page.evaluate((marks) => {
    const drawn = (window as unknown as { framesDrawn?: Record<string, number> }).framesDrawn;
    const at = (mark: string) => drawn?.[mark] ?? performance.getEntriesByName(mark)[0]!.startTime;
    return [at(marks.first), at(marks.firstComplete)];
  }, FRAME_MARKS);
  return { page, firstFrameMs, firstCompleteFrameMs };
}

/** The view measured: the painted swirl in the sky, named in full (the demo's own default view is the flowing film, src/settings/demoView.ts). */
const SWIRL_VIEW = 'field=swirl&env=sky';

export async function demoPageFigures(browser: Browser, baseUrl: string, how: DemoPlan): Promise<DemoPageFigures> {
  const still = await openDemo(browser, `${baseUrl}/?${SWIRL_VIEW}&animate=0`, how);
  const stillCounts = await countOneSecond(still.page);
  const parallelCompile = await still.page.evaluate(() =>
    (window as unknown as { bubbleView: { renderer: { extensions: { has(name: string): boolean } } } }).bubbleView.renderer.extensions.has(
      'KHR_parallel_shader_compile',
    ),
  );
  await still.page.locator('.lil-gui.lil-root > .lil-title').click(); // the panel starts closed on a small view
  const panel = await panelChanges(still.page, how.windowMs, how.panelTwice);
  await still.page.close();
  const { page, firstFrameMs, firstCompleteFrameMs } = await openDemo(browser, `${baseUrl}/?${SWIRL_VIEW}`, how);
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
  return { firstFrameMs, firstCompleteFrameMs, still: stillCounts, animating, canvasHidden, pageHidden, panel, parallelCompile };
}

/**
 * The built demo page (vite preview of dist): its first frame, and how many frames it draws and
 * tables it builds when nothing moves, while the swirl animates, and while hidden.
 */
import type { Browser, Page } from '@playwright/test';
import { FRAME_MARKS } from '../../src/app/frameMarks.ts';
import type { BenchPlan } from './benchPlan.ts';
import { openPage } from './openPage.ts';

type DemoPlan = BenchPlan['demo'];

export interface DemoPageFigures {
  /** navigation start to the first frame shown (the first animation frame after the page's first-frame mark) */
  readonly firstFrameMs: number;
  /** … to the first frame shown in full (not from a coarse table) */
  readonly firstCompleteFrameMs: number;
  /** frames drawn / tables built in one second */
  readonly still: FrameCounts;
  readonly animating: FrameCounts;
  readonly canvasHidden: FrameCounts;
  readonly pageHidden: FrameCounts;
  /** per change of PANEL_CHANGES: the longest gap between frames shown after the input, in frame intervals before it (median of the changes there and back, and the worst) */
  readonly panelLongestGap: readonly { readonly median: number; readonly max: number }[];
  /** the same, in the windows before the inputs (no change): how unevenly the page's own frames come (median of all the changes' windows, and the worst) */
  readonly unchangedLongestGap: { readonly median: number; readonly max: number };
  /** … input to the first frame shown in full, plots included, median ms */
  readonly panelChangeFullMs: readonly number[];
  /** the interval between frames shown while the swirl animates (the median of the changes’ windows before the input) */
  readonly frameMs: number;
}

/** Panel changes as a user makes them: [controller name, value, value back]. */
export const PANEL_CHANGES = [
  ['n film', '1.4', '1.33'],
  ['film material', 'water', 'constant'],
  // a change of the inside medium: air (n 1) → gold (a tabulated metal: the table's dispersive bins, an opaque inside) and back
  ['inside medium', 'Au', 'constant'],
  ['illuminant', 'D93', 'D65'],
  ['polarization', 's', 'unpolarized'],
  ['range (nm)', '1200', '800'],
] as const;

/**
 * Each change through the lil-gui panel (a number box's input event, or a list's change event),
 * there and back `panelRepeats` times, as a user sees it: the animation frames shown (requestAnimationFrame
 * timestamps) from `windowMs` before the input to `windowMs` after the frame that shows it in full; the longest
 * gap between two of them after the input, against the frame interval before it; and the time from
 * the input to the first frame shown in full with the plots drawn. The frame interval is the mean
 * over the window, the time a frame takes at the page's frame rate: where the GPU is slow (a
 * software one), frames come unevenly, often two at once and then a long gap, and the median of a
 * few gaps is then either.
 */
async function panelChanges(
  page: Page,
  how: DemoPlan,
): Promise<Pick<DemoPageFigures, 'panelLongestGap' | 'unchangedLongestGap' | 'panelChangeFullMs' | 'frameMs'>> {
  return page.evaluate(
    async ([changes, repeats, windowMs]) => {
      const view = (window as unknown as { bubbleView: { coarse: boolean } }).bubbleView;
      const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;
      const wait = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));
      const controller = (name: string) =>
        [...document.querySelectorAll<HTMLElement>('.lil-controller')].find((c) => c.querySelector('.lil-name')!.textContent === name)!;
      const set = (name: string, value: string) => {
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
      /** [longest gap after the input / mean gap before, ms to the first frame in full, the mean gap, the longest gap before / the mean]. */
      const measure = async (name: string, value: string): Promise<[number, number, number, number]> => {
        const stamps: number[] = [];
        let running = true;
        let inputAt = Infinity;
        let fullAt = Infinity;
        const tick = (t: number) => {
          stamps.push(t);
          if (t > inputAt && !view.coarse && fullAt === Infinity) fullAt = t;
          if (running) requestAnimationFrame(tick);
        };
        requestAnimationFrame(tick);
        // At least three frames before the input and two after the full one, however slow the frames.
        await wait(windowMs);
        while (stamps.length < 3) await wait(50);
        inputAt = performance.now();
        set(name, value);
        while (fullAt === Infinity) await wait(50);
        await wait(windowMs);
        while (stamps.filter((t) => t > fullAt).length < 2) await wait(50);
        running = false;
        const before = stamps.filter((t) => t < inputAt);
        const frame = (before.at(-1)! - before[0]!) / (before.length - 1);
        const after = stamps.slice(before.length - 1);
        const gapsAfter = after.slice(1).map((t, i) => t - after[i]!);
        const gapsBefore = before.slice(1).map((t, i) => t - before[i]!);
        return [Math.max(...gapsAfter) / frame, fullAt - inputAt, frame, Math.max(...gapsBefore) / frame];
      };
      const panelLongestGap: { median: number; max: number }[] = [];
      const panelChangeFullMs: number[] = [];
      const frames: number[] = [];
      const unchanged: number[] = [];
      for (const [name, value, back] of changes) {
        const runs: [number, number, number, number][] = [];
        for (let i = 0; i < repeats; i++) runs.push(await measure(name, value), await measure(name, back));
        panelLongestGap.push({ median: median(runs.map((r) => r[0])), max: Math.max(...runs.map((r) => r[0])) });
        panelChangeFullMs.push(median(runs.map((r) => r[1])));
        frames.push(...runs.map((r) => r[2]));
        unchanged.push(...runs.map((r) => r[3]));
      }
      return {
        panelLongestGap,
        unchangedLongestGap: { median: median(unchanged), max: Math.max(...unchanged) },
        panelChangeFullMs,
        frameMs: median(frames),
      };
    },
    [PANEL_CHANGES, how.panelRepeats, how.windowMs] as const,
  );
}
export interface FrameCounts {
  readonly frames: number;
  readonly tableBuilds: number;
}

const WINDOW_MS = 1000;

async function countOneSecond(page: Page): Promise<FrameCounts> {
  return page.evaluate(async (ms) => {
    const view = (window as unknown as { bubbleView: { render(quick?: boolean): void; table: { builds: number } } }).bubbleView;
    let frames = 0;
    const render = view.render.bind(view);
    view.render = (quick?: boolean) => {
      frames++;
      render(quick);
    };
    const builds = view.table.builds;
    await new Promise((r) => setTimeout(r, ms));
    view.render = render;
    return { frames, tableBuilds: view.table.builds - builds };
  }, WINDOW_MS);
}

async function open(
  browser: Browser,
  url: string,
  how: DemoPlan,
): Promise<{ page: Page; firstFrameMs: number; firstCompleteFrameMs: number }> {
  const page = await openPage(browser, { viewport: { width: how.width, height: how.height } });
  // tsx names the functions it compiles with a helper (__name) that pages evaluated from here lack.
  // From before any script runs, the timestamp of every animation frame shown.
  await page.addInitScript({
    content:
      'window.__name = (f) => f; window.shownFrames = []; (function tick(t) { window.shownFrames.push(t); requestAnimationFrame(tick); })(0);',
  });
  await page.goto(url);
  await page.waitForSelector('body[data-frames="ready"]');
  await page.waitForTimeout(200); // a frame shown after the first complete one
  const [firstFrameMs, firstCompleteFrameMs] = await page.evaluate((marks) => {
    const shown = (window as unknown as { shownFrames: number[] }).shownFrames;
    const shownAfter = (mark: string) => {
      const at = performance.getEntriesByName(mark)[0]!.startTime;
      return shown.find((t) => t > at)!;
    };
    return [shownAfter(marks.first), shownAfter(marks.firstComplete)];
  }, FRAME_MARKS);
  return { page, firstFrameMs, firstCompleteFrameMs };
}

export async function demoPageFigures(browser: Browser, baseUrl: string, how: DemoPlan): Promise<DemoPageFigures> {
  const still = await open(browser, `${baseUrl}/?animate=0`, how);
  const stillCounts = await countOneSecond(still.page);
  await still.page.close();
  const { page, firstFrameMs, firstCompleteFrameMs } = await open(browser, `${baseUrl}/`, how);
  const animating = await countOneSecond(page);
  const panel = await panelChanges(page, how);
  await page.evaluate(() => (document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = 'none'));
  const canvasHidden = await countOneSecond(page);
  await page.evaluate(() => {
    document.querySelector<HTMLCanvasElement>('#bubble')!.style.display = '';
    Object.defineProperty(document, 'hidden', { value: true });
    document.dispatchEvent(new Event('visibilitychange'));
  });
  const pageHidden = await countOneSecond(page);
  await page.close();
  return {
    firstFrameMs,
    firstCompleteFrameMs,
    still: stillCounts,
    animating,
    canvasHidden,
    pageHidden,
    ...panel,
  };
}

/**
 * The built demo's panel changes: each made through the lil-gui panel as a user makes it, and what
 * it cost the page in programs linked, long tasks and table texels, and the time to its frame in full.
 */
import type { Page } from '@playwright/test';
import { TABLE_PASS_NAME } from '../../src/film/keptPasses.ts';
import { EN } from '../../src/i18n/en.ts';
import { labelKey } from '../../src/settings/parameterRow.ts';
import { median } from './median.ts';

/** One panel change made there, back, there again and back again in a still page (the smoke: there and back). */
export interface PanelChangeFigures {
  /** programs linked by the first change there, by the first way back (to settings already shown), and by the second change there and back (null: made once) */
  readonly programs: { readonly first: number; readonly back: number; readonly second: number | null };
  /** the main thread's long tasks (over 50 ms) from the input to a frame after the first one in full, over all runs: how many, and the longest (ms, 0 for none) */
  readonly longTasks: { readonly count: number; readonly maxMs: number };
  /** the table's texels drawn by the first change there (coarse table and bands) */
  readonly texels: number;
  /** input → the first frame shown in full, plots included, median of the runs, ms */
  readonly fullMs: number;
}

/** The English panel's name of a setting's controller. */
const named = (key: string): string => EN[labelKey(key)];

/** Panel changes as a user makes them: [what, the controller's name in the English panel, value, value back]. */
export const PANEL_CHANGES: readonly (readonly [string, string, string, string])[] = [
  ['film medium', EN['panel.filmMaterial'], 'water', 'constant'],
  // air (n 1) → gold (a tabulated metal: the table's dispersive bins, an opaque inside) and back
  ['inside medium', EN['panel.insideMedium'], 'Au', 'constant'],
  ['n film', named('nFilm'), '1.4', '1.33'],
  ['light', named('illuminant'), 'D93', 'D65'],
  ['tint', EN['panel.tintGreen'], '0.5', '1'],
  ['polarisation', named('polarization'), 's', 'unpolarized'],
  ['range', named('thicknessRangeNm'), '1200', '800'],
  ['field', named('field'), 'drainage', 'swirl'],
  ['evaluation', named('mode'), 'fourier', 'table'],
];

/** A long task, as the Long Tasks API counts one: a task of the main thread over 50 ms. */
export const LONG_TASK_MS = 50;

/** The page's view and the counters the demo's init scripts keep (demoPage.ts, COUNTERS_SCRIPT). */
type Drawn = { material?: { name?: string } };
type Renderer = { render(drawn: Drawn, camera: unknown): void; getRenderTarget(): { scissor: { z: number; w: number } } | null };
type PanelWindow = {
  programsLinked: number;
  longTasks: [number, number][];
  tableTexelsDrawn: number;
  bubbleView: { lastFrame: { coarse: boolean }; renderer: Renderer };
};

/**
 * From now on, the table's texels drawn (`tableTexelsDrawn`), counted at the view's renderer: each
 * draw of the table pass (its material named TABLE_PASS_NAME) fills its target's scissor box.
 */
async function countTableTexels(page: Page): Promise<void> {
  await page.evaluate((tablePassName) => {
    const w = window as unknown as PanelWindow;
    const renderer = w.bubbleView.renderer;
    w.tableTexelsDrawn = 0;
    const render = renderer.render.bind(renderer);
    renderer.render = (drawn, camera) => {
      const target = renderer.getRenderTarget();
      if (target && drawn.material?.name === tablePassName) w.tableTexelsDrawn += target.scissor.z * target.scissor.w;
      render(drawn, camera);
    };
  }, TABLE_PASS_NAME);
}

/** One change's cost: programs linked, long tasks' durations, texels drawn, ms to the first frame shown in full. */
type ChangeCost = readonly [number, number[], number, number];

/**
 * Sets the controller named `name` to `value` (a list's change event, or a number box's input
 * event), waits until a frame is shown in full with the plots drawn and `windowMs` more have
 * passed, and returns what the change cost.
 */
async function measureChange(page: Page, name: string, value: string, windowMs: number): Promise<ChangeCost> {
  return page.evaluate(
    async ([name, value, windowMs, longTaskMs]) => {
      const w = window as unknown as PanelWindow;
      const wait = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));
      const controller = [...document.querySelectorAll<HTMLElement>('.lil-controller')].find(
        (c) => c.querySelector('.lil-name')!.textContent === name,
      );
      if (!controller) throw new Error(`the panel has no controller named ${name}`);
      const programs = w.programsLinked;
      const texels = w.tableTexelsDrawn;
      const inputAt = performance.now();
      let fullAt = Infinity;
      const tick = (t: number) => {
        if (t > inputAt && !w.bubbleView.lastFrame.coarse) fullAt = t;
        else requestAnimationFrame(tick);
      };
      const select = controller.querySelector('select');
      const input = select ?? controller.querySelector('input')!;
      input.value = value;
      input.dispatchEvent(new Event(select ? 'change' : 'input', { bubbles: true }));
      requestAnimationFrame(tick);
      while (fullAt === Infinity || !document.querySelector('.tfb-plots[data-probe]')) await wait(20);
      await wait(windowMs);
      const tasks = w.longTasks.filter(([start, ms]) => start + ms > inputAt && ms > longTaskMs).map(([, ms]) => ms);
      return [w.programsLinked - programs, tasks, w.tableTexelsDrawn - texels, fullAt - inputAt] as const;
    },
    [name, value, windowMs, LONG_TASK_MS] as const,
  );
}

/** A change's figures from its runs: there, back, and where made twice there again, back again. */
function changeFigures(runs: readonly ChangeCost[]): PanelChangeFigures {
  const tasks = runs.flatMap((r) => r[1]);
  return {
    programs: { first: runs[0]![0], back: runs[1]![0], second: runs.length > 2 ? runs[2]![0] + runs[3]![0] : null },
    longTasks: { count: tasks.length, maxMs: Math.max(0, ...tasks) },
    texels: runs[0]![2],
    fullMs: median(runs.map((r) => r[3])),
  };
}

/** Each change of PANEL_CHANGES in a still page with its panel open, there and back (`twice`: then again), each run waited for as measureChange says. */
export async function panelChanges(page: Page, windowMs: number, twice: boolean): Promise<PanelChangeFigures[]> {
  await countTableTexels(page);
  const figures: PanelChangeFigures[] = [];
  for (const [, name, value, back] of PANEL_CHANGES) {
    const runs: ChangeCost[] = [];
    for (const v of twice ? [value, back, value, back] : [value, back]) runs.push(await measureChange(page, name, v, windowMs));
    figures.push(changeFigures(runs));
  }
  await page.evaluate(() => Reflect.deleteProperty((window as unknown as PanelWindow).bubbleView.renderer, 'render'));
  return figures;
}

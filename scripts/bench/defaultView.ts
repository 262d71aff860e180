/**
 * The built demo's default view (the flowing film, governed) against the painted swirl at the same
 * size, each in a fresh browser of the same run: the first frame drawn, the mean interval between
 * animation frames, whether the film visibly evolves (its thickness at a probe 1 s apart), and what
 * the frame governor chose and when (docs/governor.md). Counts and ratios, not a rasteriser's pace.
 */
import type { Browser, Page } from '@playwright/test';
import { openDemo } from './demoPage.ts';
import { median } from './median.ts';

export interface DefaultViewPlan {
  readonly width: number;
  readonly height: number;
  /** how long each view animates after its first frame (the governor's first seconds of a bubble's life) */
  readonly seconds: number;
  /** intervals before this (ms after the first frame) are the governor's settling, not the view's pace */
  readonly settlingMs: number;
  /** the fresh browsers each view's first frame is measured in, the views taking turns; the median is quoted */
  readonly firstFrameLoads: number;
}

/** One governor choice, from the first frame drawn: the flow's grid, the pixel ratio, the steps a frame. */
export interface GovernorChoice {
  readonly atMs: number;
  readonly gridN: number | null;
  readonly pixelRatio: number;
  readonly stepsPerFrame: number;
}

export interface AnimatedView {
  /** navigation start → first frame drawn (read back as the page marks it), the median over the plan's loads (ms) */
  readonly firstFrameMs: number;
  /** mean interval between animation frames shown after the plan's settling (ms) */
  readonly meanFrameMs: number;
  readonly choices: readonly GovernorChoice[];
  /** film seconds per second of the clock after the settling (0 for a film that does not evolve) */
  readonly filmRate: number;
}

export interface DefaultViewFigures {
  readonly flow: AnimatedView & {
    /** the film's thickness (nm) at the probe, read twice 1 s apart */
    readonly probeNm: readonly [number, number];
  };
  readonly swirl: AnimatedView;
}

/** The swirl the default view is compared with: the element's default, named in full. */
const SWIRL_VIEW = 'field=swirl&env=sky';
/** Where the film is probed: a fraction of the view from the top left, on the upper half of the bubble. */
const PROBE: readonly [number, number] = [0.5, 0.35];

/**
 * From the page's first animation frame, the governor's choice whenever it changes (the view's
 * flowing film's grid, the renderer's pixel ratio, the steps a frame may take): [t, grid, ratio, steps].
 * A frame that shows a flowing film before its simulation is made (its start on the coarse grid)
 * says nothing of the grid, and is passed over.
 */
const RECORD_CHOICES = `
const v = window.bubbleView;
const f = v?.lastFrame.drawn ? v.lastFrame.film : undefined;
if (f !== undefined && (f === null || f.flow)) {
  window.shownChoices ??= [];
  const c = [t, f?.flow?.gridN ?? null, v.renderer.getPixelRatio(), window.bubbleApp.drawn.stepsPerFrame];
  const l = window.shownChoices.at(-1);
  if (!l || l[1] !== c[1] || l[2] !== c[2] || l[3] !== c[3]) window.shownChoices.push(c);
}`;

/** Animates for the plan's seconds: the frames shown and the choices made from the first frame on. */
async function animate(page: Page, how: DefaultViewPlan, firstFrameMs: number): Promise<Omit<AnimatedView, 'firstFrameMs'>> {
  return page.evaluate(
    async ([ms, first, settlingMs]) => {
      type View = { lastFrame: { film: { timeSeconds: number } | null } };
      const w = window as unknown as { bubbleView: View; shownFrames: number[]; shownChoices: [number, number | null, number, number][] };
      const wait = (forMs: number) => new Promise((done) => setTimeout(done, Math.max(0, forMs)));
      const end = performance.now() + ms;
      // Film time against the clock once the governor has settled (a change of grid starts the film anew).
      await wait(first + settlingMs - performance.now());
      const film0 = w.bubbleView.lastFrame.film?.timeSeconds ?? 0;
      const start = performance.now();
      await wait(end - start);
      const late = w.shownFrames.filter((t) => t - first >= settlingMs);
      const meanFrameMs = late.length > 1 ? (late.at(-1)! - late[0]!) / (late.length - 1) : NaN;
      const filmRate = ((w.bubbleView.lastFrame.film?.timeSeconds ?? 0) - film0) / ((performance.now() - start) / 1000);
      // The choice the first frame was shown with (made at or before it), then each change.
      const shownFirst = Math.max(0, w.shownChoices.filter(([t]) => t <= first).length - 1);
      const choices = w.shownChoices
        .slice(shownFirst)
        .map(([t, gridN, pixelRatio, stepsPerFrame]) => ({ atMs: Math.max(0, t - first), gridN, pixelRatio, stepsPerFrame }));
      return { meanFrameMs, choices, filmRate };
    },
    [how.seconds * 1000, firstFrameMs, how.settlingMs] as const,
  );
}

/** The film's thickness at the probe now (nm): the view's own probe, read back from the GPU. */
const probeThickness = (page: Page): Promise<number> =>
  page.evaluate(async ([x, y]) => {
    type View = { probe(fx: number, fy: number): Promise<{ thicknessNm: number } | null> };
    const reading = await (window as unknown as { bubbleView: View }).bubbleView.probe(x, y);
    return reading?.thicknessNm ?? NaN;
  }, PROBE);

/**
 * Each load in a browser of its own, launched by `launch` and closed after: every first frame is a
 * first visit's (no script, program or file cached by a page loaded before in the same browser).
 * The first frames: the median of the plan's loads of each view, the views taking turns; then each
 * view animates once, its frames timed from its first-frame mark with nothing read back.
 */
export async function defaultViewFigures(
  launch: () => Promise<Browser>,
  baseUrl: string,
  how: DefaultViewPlan,
): Promise<DefaultViewFigures> {
  const size = { width: how.width, height: how.height, windowMs: 0 };
  const inBrowser = async <T>(measure: (browser: Browser) => Promise<T>): Promise<T> => {
    const browser = await launch();
    try {
      return await measure(browser);
    } finally {
      await browser.close();
    }
  };
  const urls = { flow: `${baseUrl}/`, swirl: `${baseUrl}/?${SWIRL_VIEW}` };
  const firstFrames: Record<keyof typeof urls, number[]> = { flow: [], swirl: [] };
  for (let i = 0; i < how.firstFrameLoads; i++)
    for (const view of ['flow', 'swirl'] as const)
      firstFrames[view].push(await inBrowser(async (browser) => (await openDemo(browser, urls[view], size)).firstFrameMs));
  const flow = await inBrowser(async (browser) => {
    const { page, firstFrameMs } = await openDemo(browser, urls.flow, size, RECORD_CHOICES, false);
    const animated = await animate(page, how, firstFrameMs);
    const before = await probeThickness(page);
    await page.waitForTimeout(1000);
    const after = await probeThickness(page);
    return { ...animated, probeNm: [before, after] as const };
  });
  const swirl = await inBrowser(async (browser) => {
    const { page, firstFrameMs } = await openDemo(browser, urls.swirl, size, RECORD_CHOICES, false);
    return animate(page, how, firstFrameMs);
  });
  return {
    flow: { firstFrameMs: median(firstFrames.flow), ...flow },
    swirl: { firstFrameMs: median(firstFrames.swirl), ...swirl },
  };
}

const ms = (x: number) => `${x.toFixed(0)} ms`;
const choiceText = (c: GovernorChoice) =>
  `grid ${c.gridN ?? '—'}, pixel ratio ${c.pixelRatio}, ${c.stepsPerFrame} step${c.stepsPerFrame === 1 ? '' : 's'} a frame`;

/** The figures as the table docs/benchmarks.md holds: each against its goal (docs/governor.md). */
export function defaultViewMarkdown(f: DefaultViewFigures, how: DefaultViewPlan): string {
  const changes = f.flow.choices.slice(1);
  const last = changes.at(-1);
  return [
    `| the built demo's default view (the flowing film, governed) against \`${SWIRL_VIEW}\`, ${how.width}×${how.height}, each animating ${how.seconds} s in a fresh browser | value |`,
    '|---|---|',
    `| navigation start → first frame drawn, read back as the page marks it (median of ${how.firstFrameLoads} fresh browsers each, taking turns): default / swirl | ${ms(f.flow.firstFrameMs)} / ${ms(f.swirl.firstFrameMs)} (${(f.flow.firstFrameMs / f.swirl.firstFrameMs).toFixed(2)}×; goal ≤ 1.2×) |`,
    `| mean interval between animation frames after the first ${how.settlingMs / 1000} s: default / swirl | ${ms(f.flow.meanFrameMs)} / ${ms(f.swirl.meanFrameMs)} (${(f.flow.meanFrameMs / f.swirl.meanFrameMs).toFixed(2)}×; goal ≤ 1.3×) |`,
    `| the film's thickness at the probe (${PROBE.join(', ')} of the view), read 1 s apart | ${f.flow.probeNm.map((nm) => nm.toFixed(1)).join(' → ')} nm |`,
    `| film seconds per second of the clock after the first ${how.settlingMs / 1000} s | ${f.flow.filmRate.toFixed(3)} |`,
    `| the governor: its first choice | ${choiceText(f.flow.choices[0]!)} |`,
    `| … its changes in ${how.seconds} s (goal ≤ 2 in 30 s), the last at (goal ≤ 3 s after the first frame) | ${changes.length}${last ? `, ${ms(last.atMs)}: ${choiceText(last)}` : ''} |`,
  ].join('\n');
}

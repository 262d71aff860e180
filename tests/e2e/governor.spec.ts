import { expect, test, type Page } from '@playwright/test';
import { FLOW_PARAMETERS } from '../../src/physics/filmDynamics/flowParameters.ts';
import { GOVERNED_GRIDS } from '../../src/app/budgetTerms.ts';
import { EN } from '../../src/i18n/en.ts';

/**
 * The frame governor in the demo (docs/governor.md): an animating flowing film is governed, and the
 * panel's line says its film time against the clock and its grid; a grid given in the URL is
 * honoured exactly; a frozen view is not governed. One page, loaded with each URL in turn (the
 * governor is the document's: a fresh load starts it anew).
 */
type Demo = Window & {
  bubbleView: import('../../src/view/bubbleView.ts').BubbleView;
  bubbleApp: import('../../src/app/bubbleApp.ts').BubbleApp;
};

/** The panel's read-only line in the flow folder (its input's value). */
const governorLine = (page: Page) =>
  page
    .locator('.lil-gui .lil-controller')
    .filter({ has: page.getByText(EN['panel.governor'], { exact: true }) })
    .locator('input');

/** The line as the catalogue writes it, the rate and grid captured. */
const LINE = new RegExp(`^${EN['governor.line'].replace('{rate}', '([0-9.e-]+)').replace('{grid}', '(\\d+)')}$`);

/**
 * The line's rate and grid, read once it says them. One read both matches and captures: the line
 * is empty between a grid change by the governor and the next two frames of the film made anew.
 */
async function governedLine(page: Page): Promise<{ rate: number; grid: number }> {
  let said = null as RegExpExecArray | null;
  await expect.poll(async () => (said = LINE.exec(await governorLine(page).inputValue())) !== null).toBe(true);
  const [, rate, grid] = said!;
  return { rate: Number(rate), grid: Number(grid) };
}

/** The grid the view's flowing film is simulated on now (null before it is made). */
const simulated = (page: Page) => page.evaluate(() => (window as unknown as Demo).bubbleView.lastFrame.film?.flow?.gridN ?? null);

const DEFAULT_GRID = FLOW_PARAMETERS.find((r) => r.key === 'gridN')!.defaultValue;

test('an animating flow is governed and says so; a grid given is honoured; a frozen view is not governed', async ({ page }) => {
  // Animating, grid and pixel ratio left to the governor: the line names a grid of its ladder, the one simulated.
  await page.goto('/?field=flow&env=none');
  const { rate, grid } = await governedLine(page);
  expect(rate).toBeGreaterThanOrEqual(0);
  expect(GOVERNED_GRIDS).toContain(grid);

  // A grid in the URL: the film is simulated on exactly that grid, whatever the governor decides.
  await page.goto('/?field=flow&env=none&grid=24');
  expect((await governedLine(page)).grid).toBe(24);
  expect(await simulated(page)).toBe(24);
  // Further frames, further measures: still 24 (the line has been measured anew in between).
  await expect.poll(() => page.evaluate(() => (window as unknown as Demo).bubbleView.lastFrame.film?.timeSeconds ?? 0)).toBeGreaterThan(0);
  expect(await simulated(page)).toBe(24);

  // Frozen: the default grid (none given), no line, the quality's own steps per frame.
  await page.goto('/?field=flow&env=none&animate=0&time=0.001&seed=3');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  expect(await simulated(page)).toBe(DEFAULT_GRID);
  await expect(governorLine(page)).toHaveValue('');
  const steps = await page.evaluate(() => {
    const { bubbleView, bubbleApp } = window as unknown as Demo;
    return [bubbleApp.drawn.stepsPerFrame, bubbleView.quality.flowStepsPerFrame];
  });
  expect(steps[0]).toBe(steps[1]);
});

import type { ParityGroup } from '../../scripts/harness/parityCase.ts';
import { DEMO_VIEW_SETTINGS } from '../../src/settings/demoView.ts';
import { parseSettings } from '../../src/settings/settingsQuery.ts';
import { recordCentreFrames } from './centreFrames.ts';
import { centrePixel } from './drawingBuffer.ts';
import { NEUTRAL_VIEW, VIEWPORT, expect, test } from './fixtures.ts';
import { openPanel, panelTitle } from './panel.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';

/**
 * The pages a worker shares (tests/e2e/fixtures.ts) leak nothing from one test into the next.
 * Each pair runs in order in one worker (serial), so the second test gets the page the first left.
 */

test.describe('the shared demo page', () => {
  test.describe.configure({ mode: 'serial' });

  test('a test changes the settings, the viewport, the URL and the panel, and wraps the view’s render', async ({ demoPage: page }) => {
    await page.setViewportSize({ width: 320, height: 200 });
    await openPanel(page);
    await recordCentreFrames(page);
    await page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input').fill('700');
    await expect(page).toHaveURL(/thickness=700/);
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    expect(await page.evaluate(() => Object.hasOwn((window as unknown as { bubbleView: object }).bubbleView, 'render'))).toBe(true);
  });

  test('the next test gets the page as a fresh load of the neutral URL leaves it', async ({ demoPage: page }) => {
    // What the URL leaves out is the demo's default view.
    const neutral = parseSettings(NEUTRAL_VIEW.slice(1), DEMO_VIEW_SETTINGS).settings;
    const current = await page.evaluate(() => (window as unknown as { bubbleApp: { current: object } }).bubbleApp.current);
    expect(current).toEqual(neutral);
    expect(page.viewportSize()).toEqual(VIEWPORT);
    expect(new URL(page.url()).search).toBe(new URL(NEUTRAL_VIEW, 'http://x').search);
    await expect(panelTitle(page)).toHaveAttribute('aria-expanded', 'false');
    // The panel shows the neutral values, not the last test's.
    await openPanel(page);
    await expect(page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input')).toHaveValue('450');
    expect(await page.evaluate(() => Object.hasOwn((window as unknown as { bubbleView: object }).bubbleView, 'render'))).toBe(false);
    expect(worstCodeDifference(await centrePixel(page), reference8({ thicknessNm: 450 }))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  });
});

test('the shared parity page gives the same numbers for the same cases, whatever it rendered between', async ({ parityPage: page }) => {
  const group = (nFilm: number, polarization: 's' | 'p'): ParityGroup => ({
    nOutside: 1,
    nFilm,
    nInside: 1,
    illuminant: 'D65',
    polarization,
    normalization: 'white',
    inputs: [
      [0, 1],
      [450, 1],
      [1200, 0.5],
    ],
  });
  const render = (g: ParityGroup, mode: 'table' | 'exact') =>
    page.evaluate(([gs, m]) => window.renderFilmXyz!(gs, m), [[g], mode] as const);
  const first = await render(group(1.33, 's'), 'table');
  await render(group(2.1, 'p'), 'exact');
  await render(group(1.5, 'p'), 'table');
  expect(await render(group(1.33, 's'), 'table')).toEqual(first);
});

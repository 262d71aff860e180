import { test as base, expect, type Browser, type Page } from '@playwright/test';
import type { ViewSettings } from '../../src/settings/viewParameters.ts';
import { BUILT_URL } from './servers.ts';
import { panelTitle } from './panel.ts';

/**
 * Pages shared by the tests of one worker, so that each harness compiles its programs once per
 * worker instead of once per test:
 * - `parityPage`: the float-target harness (tests/e2e/harness/parity.html). It keeps no state
 *   between calls: each renders its cases with its own passes and returns the numbers.
 * - `demoPage`: the demo at NEUTRAL_VIEW. Before each test it is put back as a fresh load of that
 *   URL leaves it (demoPageReset): the settings and the panel's values, the URL, the viewport, a
 *   closed panel, the view's own `render`.
 * A test that needs what only a fresh page gives (its first frame, a lost context, a browser
 * without WebGL, a cold load's access, the soak's heap) takes Playwright's own `page` and says why.
 */

/** The demo's neutral view: a uniform 450 nm film, head-on, nothing behind it, still. */
export const NEUTRAL_VIEW = '/?field=uniform&thickness=450&env=none&sides=front&exposure=1&animate=0';
/** The viewport of every test's page unless it sets its own (playwright.config.ts). */
export const VIEWPORT = { width: 640, height: 480 } as const;

type Demo = Window & {
  bubbleApp: import('../../src/app/bubbleApp.ts').BubbleApp;
  bubbleView: import('../../src/view/bubbleView.ts').BubbleView;
};

async function sharedPage(browser: Browser, path: string, readiness: readonly [string, string]): Promise<Page> {
  const context = await browser.newContext({ baseURL: BUILT_URL, viewport: VIEWPORT });
  const page = await context.newPage();
  await page.goto(path);
  await expect(page.locator('body')).toHaveAttribute(...readiness);
  return page;
}

/** The shared demo page and the settings a fresh load of NEUTRAL_VIEW gives. */
interface SharedDemo {
  readonly page: Page;
  readonly neutral: ViewSettings;
}

/**
 * Puts the shared demo back as a fresh load of NEUTRAL_VIEW leaves it, and waits for a frame drawn
 * in full with those settings.
 */
export async function demoPageReset({ page, neutral }: SharedDemo): Promise<void> {
  await page.setViewportSize(VIEWPORT);
  if ((await panelTitle(page).getAttribute('aria-expanded')) === 'true') await panelTitle(page).click();
  await page.evaluate(
    ([settings, url]) => {
      const { bubbleApp, bubbleView } = window as unknown as Demo;
      // A test may have wrapped the view's render (centreFrames.ts): the prototype's is the view's own.
      delete (bubbleView as Partial<Pick<typeof bubbleView, 'render'>>).render;
      document.body.dataset.frames = 'changed';
      bubbleApp.set(settings, true);
      history.replaceState(null, '', url);
    },
    [neutral, NEUTRAL_VIEW] as const,
  );
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
}

export const test = base.extend<{ parityPage: Page; demoPage: Page }, { sharedParity: Page; sharedDemo: SharedDemo }>({
  sharedParity: [
    ({ browser }, use) => sharedPage(browser, '/tests/e2e/harness/parity.html', ['data-ready', 'yes']).then(use),
    { scope: 'worker' },
  ],
  sharedDemo: [
    async ({ browser }, use) => {
      const page = await sharedPage(browser, NEUTRAL_VIEW, ['data-frames', 'ready']);
      const neutral = await page.evaluate(() => (window as unknown as Demo).bubbleApp.current);
      await use({ page, neutral });
    },
    { scope: 'worker' },
  ],
  parityPage: ({ sharedParity }, use) => use(sharedParity),
  demoPage: async ({ sharedDemo }, use) => {
    await demoPageReset(sharedDemo);
    await use(sharedDemo.page);
  },
});

/**
 * The tag of the tests also run on the WebGL backend TFC_GL does not name (the `webgl-other`
 * project of playwright.config.ts, alone: `npm run test:e2e:other-backend`): the table, the flow,
 * the material and a lost context, so that neither backend rots.
 */
export const BOTH_BACKENDS = '@both-backends';

export { expect };

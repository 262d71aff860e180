import { expect, test, type Locator, type Page } from '@playwright/test';
import { panelTitle } from './panel.ts';

/**
 * The layout for any size: on a phone (390×844) and at 640×480 the demo's panel starts closed
 * and its plots are below the bubble (portrait) or in a closed drawer, so what is at the bubble's
 * centre is the canvas (the camera looks at the bubble's centre: it is the view's centre); a view
 * with room (1100×720; the element, whose plots take a column, 1280×720) keeps both open. The element does the same for its own box. A tap moves
 * the probe.
 */

const PHONE = { width: 390, height: 844 };
const SMALL = { width: 640, height: 480 };
const WIDE = { width: 1100, height: 720 };
/** Room for the element's plots column (270 px) beside a stage as large as the demo needs for its panel (900×600). */
const WIDE_ELEMENT = { width: 1280, height: 720 };
const FILM = 'field=uniform&thickness=450&env=none&sides=front&animate=0';

/** What `document.elementFromPoint` finds at the centre of `canvas`'s box, and whether it is that canvas. */
const atCentre = (canvas: Locator) =>
  canvas.evaluate((c) => {
    const box = c.getBoundingClientRect();
    const found = document.elementFromPoint(box.left + box.width / 2, box.top + box.height / 2);
    return { isCanvas: found === c, found: found ? `${found.tagName.toLowerCase()}.${found.className}` : 'nothing' };
  });

async function openDemo(page: Page, size: { width: number; height: number }): Promise<void> {
  await page.setViewportSize(size);
  await page.goto(`/?${FILM}`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
}

for (const [size, plots] of [
  [PHONE, 'below'],
  [SMALL, 'drawer'],
] as const) {
  test(`demo at ${size.width}×${size.height}: the panel starts closed, the plots ${plots === 'below' ? 'are below the bubble' : 'start in a closed drawer'}, the canvas is at the bubble's centre`, async ({
    page,
  }) => {
    await openDemo(page, size);
    const canvas = page.locator('#bubble');
    expect(await atCentre(canvas)).toEqual({ isCanvas: true, found: 'canvas.tfb-focusable' });
    await expect(panelTitle(page)).toHaveAttribute('aria-expanded', 'false');
    const drawer = page.locator('#plots-box');
    if (plots === 'below') {
      await expect(drawer).toHaveJSProperty('open', true);
      const [bubble, box] = [(await canvas.boundingBox())!, (await drawer.boundingBox())!];
      expect(box.y).toBeGreaterThanOrEqual(bubble.y + bubble.height);
      // The bubble fits the phone's width: its view is as wide as it is tall.
      expect(bubble.height).toBe(bubble.width);
    } else {
      await expect(drawer).toHaveJSProperty('open', false);
      // The drawer's summary opens it.
      await drawer.locator('summary').click();
      await expect(drawer).toHaveJSProperty('open', true);
      await expect(page.locator('.tfb-spectrum')).toBeVisible();
    }
  });
}

test('demo at 1100×720: the panel and the plots start open beside the bubble, the canvas at its centre', async ({ page }) => {
  await openDemo(page, WIDE);
  expect(await atCentre(page.locator('#bubble'))).toEqual({ isCanvas: true, found: 'canvas.tfb-focusable' });
  await expect(panelTitle(page)).toHaveAttribute('aria-expanded', 'true');
  await expect(page.locator('#plots-box')).toHaveJSProperty('open', true);
});

/** A page on the dev server holding one element with its panel and plots, filling the view. */
async function openElement(page: Page, size: { width: number; height: number }): Promise<Locator> {
  await page.setViewportSize(size);
  await page.route('**/layout.html', (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><meta charset="utf-8"><script type="module" src="/thin-film-bubble.js"></script>
<style>body { margin: 0 } thin-film-bubble { height: 100vh }</style>
<thin-film-bubble controls plots ${FILM.replaceAll('&', ' ').replaceAll(/=(\w+)/g, '="$1"')}></thin-film-bubble>`,
    }),
  );
  await page.goto('/layout.html');
  const el = page.locator('thin-film-bubble');
  await expect(el).toHaveAttribute('data-frames', /\d+/);
  return el;
}

for (const size of [PHONE, SMALL]) {
  test(`element with controls and plots at ${size.width}×${size.height}: panel and plots drawer start closed, the canvas at the bubble's centre`, async ({
    page,
  }) => {
    const el = await openElement(page, size);
    expect(await atCentre(el.locator('.tfb-stage > canvas'))).toEqual({ isCanvas: true, found: 'canvas.tfb-focusable' });
    await expect(el.locator('.lil-gui.lil-root > .lil-title')).toHaveAttribute('aria-expanded', 'false');
    await expect(el.locator('details.tfb-side')).toHaveJSProperty('open', false);
  });
}

test('element with controls and plots at 1280×720: the panel and the plots start open', async ({ page }) => {
  const el = await openElement(page, WIDE_ELEMENT);
  expect(await atCentre(el.locator('.tfb-stage > canvas'))).toEqual({ isCanvas: true, found: 'canvas.tfb-focusable' });
  await expect(el.locator('.lil-gui.lil-root > .lil-title')).toHaveAttribute('aria-expanded', 'true');
  await expect(el.locator('details.tfb-side')).toHaveJSProperty('open', true);
});

test.describe('touch', () => {
  test.use({ hasTouch: true });
  for (const size of [PHONE, SMALL]) {
    test(`a tap at ${size.width}×${size.height} moves the probe there, and into the URL`, async ({ page }) => {
      await openDemo(page, size);
      await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', '0.5,0.5 bubble');
      const box = (await page.locator('#bubble').boundingBox())!;
      const [fx, fy] = [0.6, 0.4]; // whole pixels at both sizes
      await page.touchscreen.tap(box.x + fx * box.width, box.y + fy * box.height);
      await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', `${fx},${fy} bubble`);
      await expect(page).toHaveURL(new RegExp(`probe=${fx}%2C${fy}(&|$)`));
    });
  }
});

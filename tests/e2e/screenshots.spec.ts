import { expect, test, type Page } from '@playwright/test';
import { PANEL, PLOTS } from '../../scripts/render/demoPage.ts';

/**
 * The look, guarded by screenshots made deterministic first: animate=0 freezes the
 * field at a fixed `time`, the viewport is fixed at 640×480 (playwright.config.ts), and the
 * default `table` mode keeps SwiftShader fast. The numbers are guarded by parity.spec.ts.
 */

/** YIQ distance under which two pixels count as equal (Playwright's scale, 0–1): ~5 codes of luma.
 * SwiftShader renders deterministically; the film's reflection is faint over the sky, so 0.1 would
 * let a wrong film colour through. */
const PIXEL_THRESHOLD = 0.03;
/** Pixels allowed to differ: the sphere's antialiased rim. */
const MAX_DIFF_PIXEL_RATIO = 0.01;

/** The painted fields in the procedural sky, each named in full (the demo's own default view is the flow on black). */
const VIEWS = {
  'swirl-t0': '/?field=swirl&env=sky&animate=0&time=0',
  'drainage-d93': '/?field=drainage&env=sky&illuminant=D93&animate=0&time=0',
  'uniform-350nm': '/?field=uniform&env=sky&thickness=350&animate=0&time=0',
  'swirl-t5': '/?field=swirl&env=sky&animate=0&time=5',
};

/** Draws a frame and sums up the middle 160×160 pixels, where the bubble is, from the drawing buffer. */
async function bubbleStats(page: Page): Promise<{ distinctColors: number; meanLevel: number }> {
  return page.evaluate(() => {
    const view = (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView;
    view.render();
    const gl = view.renderer.getContext();
    const size = 160;
    const pixels = new Uint8Array(4 * size * size);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels((gl.drawingBufferWidth - size) >> 1, (gl.drawingBufferHeight - size) >> 1, size, size, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const colors = new Set<number>();
    let sum = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      colors.add((pixels[i]! << 16) | (pixels[i + 1]! << 8) | pixels[i + 2]!);
      sum += pixels[i]! + pixels[i + 1]! + pixels[i + 2]!;
    }
    return { distinctColors: colors.size, meanLevel: sum / (3 * size * size) };
  });
}

for (const [name, url] of Object.entries(VIEWS)) {
  test(`screenshot: ${name}`, async ({ page }) => {
    await page.goto(url);
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    await expect(page.locator('#messages')).toBeEmpty();
    const { distinctColors, meanLevel } = await bubbleStats(page);
    console.log(`screenshot ${name}: ${distinctColors} distinct colours, mean level ${meanLevel.toFixed(1)} in the bubble's middle`);
    // Neither blank nor black: a lit film shows many colours at a visible level (black is 0,
    // a uniform film still shades with θ_i).
    expect(distinctColors).toBeGreaterThan(30);
    expect(meanLevel).toBeGreaterThan(20);
    // The control panel and the plots are UI, not the look under test: hidden.
    await page.addStyleTag({ content: `${PANEL}, ${PLOTS} { display: none !important; }` });
    await expect(page).toHaveScreenshot(`${name}.png`, { threshold: PIXEL_THRESHOLD, maxDiffPixelRatio: MAX_DIFF_PIXEL_RATIO });
  });
}

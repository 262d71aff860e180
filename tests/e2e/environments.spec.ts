import { expect, test, type Page, type Route } from '@playwright/test';
import { KEPT_DEFINE_SETS } from '../../src/gpu/materialDefines.ts';
import { HDR_ENVIRONMENTS } from '../../src/settings/filmSettings.ts';
import { showSettings } from './appSettings.ts';
import { watchProblems } from './pageWatch.ts';
import { gpuObjects, loseContext, restoreContext, settledGpuObjects } from './webglContext.ts';

/**
 * The HDR environments as a page meets them: each arrives (its own module, fetched when first
 * shown) with no console error and draws a bubble that is not uniform, and a lost and restored GPU
 * context draws the same bubble again; while one is on its way the page says so and counts no
 * frame as ready; one that fails to load says so and shows the sky.
 */

type Window_ = Window & { bubbleView: import('../../src/view/bubbleView.ts').BubbleView };
const DRAINED = 'field=drainage&thickness=600&thicknessRange=1100&animate=0';

/** The drawing buffer's pixels, drawn afresh, with the spread of luminance over the bubble's middle third. */
const frame = (page: Page) =>
  page.evaluate(() => {
    const view = (window as unknown as Window_).bubbleView;
    view.render();
    const gl = view.renderer.getContext();
    const w = gl.drawingBufferWidth,
      h = gl.drawingBufferHeight;
    const pixels = new Uint8Array(4 * w * h);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const levels: number[] = [];
    for (let y = Math.round(h / 3); y < (2 * h) / 3; y += 2)
      for (let x = Math.round(w / 2 - h / 6); x < w / 2 + h / 6; x += 2) {
        const i = 4 * (y * w + x);
        levels.push(0.2126 * pixels[i]! + 0.7152 * pixels[i + 1]! + 0.0722 * pixels[i + 2]!);
      }
    const mean = levels.reduce((a, b) => a + b, 0) / levels.length;
    const spread = Math.sqrt(levels.reduce((a, b) => a + (b - mean) ** 2, 0) / levels.length);
    // Black pixels around where park turned 120° puts the sun (behind the bubble's top right, in a 640×480 view).
    let black = 0;
    for (let y = Math.round(h * 0.7); y < h * 0.9; y++)
      for (let x = Math.round(w * 0.55); x < w * 0.7; x++) {
        const i = 4 * (y * w + x);
        if (Math.max(pixels[i]!, pixels[i + 1]!, pixels[i + 2]!) < 8) black++;
      }
    // The pixels as base64, compared exactly (a million numbers took seconds to bring back and compare).
    let bytes = '';
    for (let i = 0; i < pixels.length; i += 0x8000) bytes += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
    return { pixels: btoa(bytes), spread, black };
  });

/** An environment's module, as the dev server or the build names it. */
const environmentModule = (env: string) => (url: URL) => url.pathname.includes(env) && url.pathname.includes('exr');

test('every HDR environment loads without a console error and draws a bubble that is not uniform; a lost and restored context draws the last one again, nothing leaked', async ({
  page,
}) => {
  const problems = watchProblems(page);
  // park turned 120°, asked for by the URL: the sun sits behind the bubble's top right, seen through it.
  await page.goto(`/?env=park&envRotation=120&${DRAINED}`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  await expect(page.locator('.environment-status')).toHaveCount(0);
  const { black } = await frame(page);
  console.log(`park turned 120°: ${black} black pixels near its sun`);
  // The sun's negative ringing in the map, unclipped, drew ~900 black pixels around it through AgX.
  expect(black).toBe(0);
  for (const env of HDR_ENVIRONMENTS) {
    // Each environment in the same page, as the panel sets it (its module fetched when first shown).
    await showSettings(page, { env, envRotationDeg: 0 });
    await expect(page.locator('.environment-status')).toHaveCount(0);
    const { spread } = await frame(page);
    console.log(`${env}: luminance spread ${spread.toFixed(1)} levels over the bubble's middle`);
    // A uniform (or black, or empty) bubble has no spread; the reflected scenes give tens of levels.
    expect(spread, env).toBeGreaterThan(5);
  }

  const before = await frame(page);
  const objects = await settledGpuObjects(page);
  await loseContext(page);
  await restoreContext(page);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  expect((await frame(page)).pixels === before.pixels, 'the same pixels after the restore').toBe(true);
  // Nothing leaked: as many geometries and textures; the restored context makes only the programs
  // the frame and the plots draw with, not those the materials kept for other settings (KEPT_DEFINE_SETS).
  await expect
    .poll(async () => {
      const now = await gpuObjects(page);
      return { ...now, programs: now.programs <= objects.programs && now.programs > objects.programs - KEPT_DEFINE_SETS };
    })
    .toEqual({ ...objects, programs: true });
  expect(problems).toEqual([]);
});

test('a loading environment is announced and counts no frame as ready; a failed one says so and shows the sky', async ({ page }) => {
  const held: Route[] = [];
  await page.route(environmentModule('sunset'), (route) => void held.push(route));
  await page.goto(`/?env=sunset&${DRAINED}`);
  const line = page.locator('.environment-status');
  await expect(line).toHaveText(/Loading the environment sunset/);
  await expect.poll(() => held.length).toBe(1);
  expect(await page.locator('body').getAttribute('data-frames')).toBeNull();
  await held[0]!.abort();
  await expect(line).toHaveText(/sunset could not be loaded .*showing the sky/);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const fallback = await frame(page);

  // The same view asking for the sky itself.
  await showSettings(page, { env: 'sky' });
  await expect(line).toHaveCount(0);
  expect((await frame(page)).pixels === fallback.pixels, 'the same pixels as the sky asked for').toBe(true);
});

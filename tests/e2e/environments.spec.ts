import type { Page, Route } from '@playwright/test';
import { expect, test } from './fixtures.ts';
import { KEPT_DEFINE_SETS } from '../../src/gpu/materialDefines.ts';
import { encode8, srgbDecode } from '../../src/physics/colorConversions.ts';
import { HDR_ENVIRONMENTS } from '../../src/settings/filmSettings.ts';
import { parseSettings } from '../../src/settings/settingsQuery.ts';
import { showSettings } from './appSettings.ts';
import { centrePixel } from './drawingBuffer.ts';
import { openPanel } from './panel.ts';
import { EN } from '../../src/i18n/en.ts';
import { MAX_CODE_DIFFERENCE, worstCodeDifference } from './referenceColor.ts';
import { watchProblems } from './pageWatch.ts';
import { gpuObjects, loseContext, restoreContext, settledGpuObjects } from './webglContext.ts';

/**
 * The HDR environments as a page meets them: each arrives (its own module, fetched when first
 * shown) with no console error and draws a bubble that is not uniform, and a lost and restored GPU
 * context draws the same bubble again; while one is on its way the page says so and counts no
 * frame as ready; one that fails to load says so and shows the sky. A uniform colour, given in the
 * URL's text, lights the bubble linearly and changes colour without a new program.
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

test("a grey room of g (env=color:g,g,g) shows a bare metal's linear colour under env=none times g and the grey behind; a new grey compiles nothing", async ({
  demoPage: page,
}) => {
  /** The corner pixel: the background, off the bubble. */
  const cornerPixel = () =>
    page.evaluate(() => {
      const gl = (window as unknown as Window_).bubbleView.renderer.getContext();
      const pixel = new Uint8Array(4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.readPixels(2, 2, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      return [pixel[0]!, pixel[1]!, pixel[2]!];
    });
  /** The view `query` gives over the shared page's neutral one (tone mapping auto), its centre and corner. */
  const shown = async (query: string) => {
    const { settings, refusals } = parseSettings(`${query}&nInside=Cu&thickness=0`);
    expect(refusals).toEqual([]);
    const { env, nInside, thicknessNm } = settings;
    await showSettings(page, { env, nInside, thicknessNm });
    return { centre: await centrePixel(page), corner: await cornerPixel() };
  };
  // Bare copper under the light's white, (0.94, 0.62, 0.52) in linear sRGB: no channel clips, so each says how much light it reflects.
  const white = await shown('env=none');
  expect(Math.max(...white.centre)).toBeLessThan(255);
  for (const g of [0.5, 0.25]) {
    const grey = await shown(`env=color:${g},${g},${g}`);
    // Linear in the light reflected: the linear colour under the light's white, times g (tone mapping auto is none here).
    const expected = white.centre.map((code) => encode8(g * srgbDecode(code / 255)));
    console.log(`copper in grey ${g}: centre ${grey.centre}, expected ${expected} (under white ${white.centre}); corner ${grey.corner}`);
    expect(worstCodeDifference(grey.centre, expected), `centre in grey ${g}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    expect(worstCodeDifference(grey.corner, [encode8(g), encode8(g), encode8(g)]), `corner in grey ${g}`).toBeLessThanOrEqual(
      MAX_CODE_DIFFERENCE,
    );
  }
  // The second grey drew with the first one's programs: a colour is a uniform, not a define.
  const programs = (await gpuObjects(page)).programs;
  const red = await shown('env=color:1,0.2,0.2');
  expect((await gpuObjects(page)).programs).toBe(programs);
  expect(worstCodeDifference(red.corner, [encode8(1), encode8(0.2), encode8(0.2)]), 'corner in red').toBeLessThanOrEqual(
    MAX_CODE_DIFFERENCE,
  );
});

test('the panel shows a uniform colour the URL gives as its own choice with R, G and B sliders, and writes the colour and a name back', async ({
  page,
}) => {
  // A fresh page: the panel is made from the settings of the URL it loads.
  const problems = watchProblems(page);
  await page.goto('/?env=color:1,0.2,0.2&field=uniform&thickness=450&sides=front&animate=0');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  await openPanel(page);
  const env = page.getByRole('combobox', { name: 'environment', exact: true });
  const slider = (c: string) => page.locator('.lil-controller', { hasText: `environment ${c} (linear sRGB)` });
  // lil-gui's options are valued by their labels.
  await expect(env).toHaveValue(EN['choice.env.color']);
  await expect(slider('R').locator('input')).toHaveValue('1');
  await expect(slider('G').locator('input')).toHaveValue('0.2');
  await slider('G').locator('input').fill('0.5');
  await slider('G').locator('input').press('Enter');
  await expect(page).toHaveURL(/env=color(:|%3A)1(,|%2C)0\.5(,|%2C)0\.2(&|$)/);
  await env.selectOption('sky');
  await expect(page).toHaveURL(/env=sky/);
  for (const c of ['R', 'G', 'B']) await expect(slider(c)).toBeHidden();
  // Back to the colour: the sliders kept theirs.
  await env.selectOption(EN['choice.env.color']);
  await expect(page).toHaveURL(/env=color(:|%3A)1(,|%2C)0\.5(,|%2C)0\.2(&|$)/);
  for (const c of ['R', 'G', 'B']) await expect(slider(c)).toBeVisible();
  expect(problems).toEqual([]);
});

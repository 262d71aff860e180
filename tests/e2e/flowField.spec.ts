import { expect, test, type Page } from '@playwright/test';
import { cubeSphereGrid } from '../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { nearestCell } from '../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { type Demo, type FilmReader, installFilmReader, paddedFilmCells } from './demoFlowFilm.ts';
import { openPanel } from './panel.ts';
import { watchProblems } from './pageWatch.ts';
import { gpuObjects, loseContext, restoreContext, settledGpuObjects } from './webglContext.ts';

/**
 * field=flow in the demo: a frozen time is simulated in whole fixed steps from the seeded start, so
 * the same URL draws the same pixels on every load, and again after a lost context; a frozen view
 * draws nothing after its frame. A small grid keeps SwiftShader quick.
 */
const GRID_N = 16;
const FROZEN = `/?field=flow&grid=${GRID_N}&seed=5&wind=0.5&animate=0&time=0.06&env=none`;
/**
 * The wind thins that film to its rupture thickness at 0.126 s; the rims sweep the sphere within
 * that 4.9 ms step, and with renew the film is new again 0.25 s (RENEW_DELAY_S) after that.
 */
const RENEWED_S = 0.45;

/** The drawing buffer as the page last drew it (a hash of every byte and how many are lit), and the film's steps. */
const drawn = (page: Page) =>
  page.evaluate(() => {
    const view = (window as unknown as Demo).bubbleView;
    const gl = view.renderer.getContext();
    const pixels = new Uint8Array(4 * gl.drawingBufferWidth * gl.drawingBufferHeight);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    let hash = 2166136261;
    let lit = 0;
    for (const byte of pixels) {
      hash = Math.imul(hash ^ byte, 16777619) >>> 0;
      if (byte > 8) lit++;
    }
    const flow = view.lastFrame.film?.flow;
    return { hash, lit, steps: flow?.steps ?? -1, stepSeconds: flow?.stepSeconds ?? 0 };
  });

async function load(page: Page, url: string) {
  await page.goto(url);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  return drawn(page);
}

test('field=flow at a frozen time draws the same pixels on every load, the film simulated to that time', async ({ page }) => {
  const problems = watchProblems(page);
  const first = await load(page, FROZEN);
  expect(first.steps).toBe(Math.floor(0.06 / first.stepSeconds));
  expect(first.lit, 'a lit bubble').toBeGreaterThan(1000);
  const second = await load(page, FROZEN);
  expect(second).toEqual(first);
  // The time matters: another time is another film.
  const later = await load(page, FROZEN.replace('time=0.06', 'time=0.1'));
  expect(later.hash).not.toBe(first.hash);
  expect(problems).toEqual([]);
});

test('a burst film is gone for good with renew=0; with renew=1 a whole new bubble follows', async ({ page }) => {
  await page.addInitScript(installFilmReader);
  const at = (seconds: number, renew: number) => load(page, `${FROZEN.replace('time=0.06', `time=${seconds}`)}&renew=${renew}`);
  const intactCells = async () =>
    paddedFilmCells(await page.evaluate(() => (window as unknown as FilmReader).flowFilmTexels()), GRID_N).intact.reduce(
      (s, v) => s + v,
      0,
    );
  const gone = await at(RENEWED_S, 0);
  expect(await intactCells()).toBe(0);
  const renewed = await at(RENEWED_S, 1);
  expect(await intactCells()).toBe(6 * GRID_N * GRID_N);
  expect(renewed.hash).not.toBe(gone.hash);
});

test('a frozen flowing film draws nothing after its frame', async ({ page }) => {
  await load(page, FROZEN);
  const frames = () => page.evaluate(() => (window as unknown as Demo).bubbleView.renderer.info.render.frame);
  const before = await frames();
  // Ten animation frames of the page's own: an app still drawing would have drawn in each (it draws in
  // requestAnimationFrame), however slow the machine, and three counts every render.
  const animationFrames = await page.evaluate(async () => {
    let count = 0;
    while (count < 10) await new Promise((resolve) => requestAnimationFrame(() => resolve(count++)));
    return count;
  });
  expect(animationFrames).toBe(10);
  expect(await frames()).toBe(before);
});

test('after a lost context the flowing film is simulated again from its start to the same frozen time, without a WebGL warning', async ({
  page,
}) => {
  const problems = watchProblems(page);
  const before = await load(page, FROZEN);
  const objects = await settledGpuObjects(page);
  await loseContext(page);
  await restoreContext(page);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  expect(await drawn(page)).toEqual(before);
  // The restored film's targets and textures replace the lost ones: nothing leaked.
  await expect.poll(() => gpuObjects(page)).toEqual(objects);
  // A new film after the restore (its own targets), and the one it replaces disposed: no warning either.
  await page.evaluate(() => {
    const { bubbleView, bubbleApp } = window as unknown as Demo;
    bubbleApp.set({ ...bubbleApp.current, seed: 6 });
    bubbleView.render();
  });
  expect(problems).toEqual([]);
});

test("B on the bubble, or Enter on the panel's blow button, blows at the probe, to the right: the film there moves right", async ({
  page,
}) => {
  await page.addInitScript(installFilmReader);
  // Still air, so the blow is the only air.
  await load(page, FROZEN.replace('wind=0.5', 'wind=0'));
  await openPanel(page);
  const button = page.getByRole('button', { name: 'blow (B)' });
  /** η at the front of the bubble 0.3 rad right and left of the centre, 0.03 s of film after the time, blown (by B, by the button) or not. */
  const filmAfter = async (blow: 'none' | 'key' | 'button') => {
    if (blow === 'button') await button.press('Enter');
    const texels = await page.evaluate((withKey) => {
      const { bubbleView, bubbleApp } = window as unknown as Demo;
      const start = bubbleApp.current.timeSeconds;
      if (withKey) document.querySelector<HTMLElement>('[role=application]')!.dispatchEvent(new KeyboardEvent('keydown', { key: 'b' }));
      bubbleApp.set({ ...bubbleApp.current, timeSeconds: start + 0.03 });
      bubbleView.render();
      const film = (window as unknown as FilmReader).flowFilmTexels();
      bubbleApp.set({ ...bubbleApp.current, timeSeconds: start });
      bubbleView.render();
      return film;
    }, blow === 'key');
    return [...paddedFilmCells(texels, GRID_N).eta];
  };
  const calm = await filmAfter('none');
  const grid = cubeSphereGrid(GRID_N);
  // The view's front (0, 0, 1) is the simulation's (0, −1, 0); the view's right, +x, is its +x.
  const [right, left] = [0.3, -0.3].map((a) => nearestCell(grid, Math.sin(a), -Math.cos(a), 0));
  const [byKey, byButton] = [await filmAfter('key'), await filmAfter('button')];
  expect(byKey[right!]! - calm[right!]!).toBeGreaterThan(1e-3);
  expect(byKey[left!]! - calm[left!]!).toBeLessThan(-1e-3);
  // The button blows as the key does.
  expect(byButton).toEqual(byKey);
});

test('showing the flowing film and leaving it again, five times, leaves the live GPU objects as after the first time', async ({ page }) => {
  const problems = watchProblems(page);
  await load(page, FROZEN.replace('field=flow', 'field=uniform'));
  const objects = await settledGpuObjects(page);
  const showAndLeave = (times: number) =>
    page.evaluate((n) => {
      const { bubbleView, bubbleApp } = window as unknown as Demo;
      for (let i = 0; i < n; i++)
        for (const field of ['flow', 'uniform'] as const) {
          bubbleApp.set({ ...bubbleApp.current, field });
          bubbleView.render();
        }
    }, times);
  await showAndLeave(1);
  const afterFirst = await gpuObjects(page);
  // The simulation's own targets, textures and programs are gone; the bubble keeps the program of the
  // flow's defines (KEPT_DEFINE_SETS), so that showing it again compiles nothing: one program more.
  expect(afterFirst).toEqual({ ...objects, programs: objects.programs + 1 });
  await showAndLeave(4);
  await expect.poll(() => gpuObjects(page)).toEqual(afterFirst);
  expect(problems).toEqual([]);
});

import { expect, test, type Page } from '@playwright/test';
import { centrePixel } from './drawingBuffer.ts';
import { openPanel } from './panel.ts';
import { watchProblems } from './pageWatch.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';

/**
 * The GPU going away and coming back (WEBGL_lose_context): the bubble redraws by itself with its
 * table rebuilt (a table left empty would draw black, not the reference colour), and three's
 * count of live GPU objects is what it was (nothing leaked by the restore).
 */

type Window_ = Window & { bubbleView: import('../../src/scene/bubbleView.ts').BubbleView };

const gpuObjects = (page: Page) =>
  page.evaluate(() => {
    const { info } = (window as unknown as Window_).bubbleView.renderer;
    return { geometries: info.memory.geometries, textures: info.memory.textures, programs: info.programs?.length ?? 0 };
  });

for (const mode of ['table', 'exact'] as const) {
  test(`${mode} mode: after a lost and restored context the bubble redraws itself, table rebuilt, nothing leaked`, async ({ page }) => {
    const problems = watchProblems(page);
    await page.setViewportSize({ width: 320, height: 240 });
    await page.goto(`/?field=uniform&thickness=450&env=none&sides=front&animate=0&mode=${mode}`);
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    const expected = reference8({ thicknessNm: 450 });
    expect(worstCodeDifference(await centrePixel(page, false), expected)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    await openPanel(page);
    const before = await gpuObjects(page);

    await page.evaluate(async () => {
      const canvas = (window as unknown as Window_).bubbleView.renderer.domElement;
      const gl = canvas.getContext('webgl2')!;
      const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
      // A lost context gives no extensions: keep this one to restore it with.
      const extension = gl.getExtension('WEBGL_lose_context')!;
      Object.assign(window, { loseContextExtension: extension });
      extension.loseContext();
      await lost;
      document.body.dataset.frames = 'lost';
    });
    // While lost, a change of settings must not throw (nothing can be drawn).
    await page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input').fill('450');
    await page.evaluate(() => (window as unknown as { loseContextExtension: WEBGL_lose_context }).loseContextExtension.restoreContext());
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    expect(worstCodeDifference(await centrePixel(page, false), expected), 'centre after restore').toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    expect(await gpuObjects(page)).toEqual(before);
    expect(problems).toEqual([]);
  });
}

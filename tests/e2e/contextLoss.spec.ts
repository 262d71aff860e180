import { BOTH_BACKENDS, expect, test } from './fixtures.ts';
import { methodReads } from '../../src/methods/methods.ts';
import { centrePixel } from './drawingBuffer.ts';
import { openPanel } from './panel.ts';
import { watchProblems } from './pageWatch.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';
import { gpuObjects, loseContext, restoreContext, settledGpuObjects } from './webglContext.ts';

/**
 * The GPU going away and coming back (WEBGL_lose_context): the bubble redraws by itself with its
 * table rebuilt (a table left empty would draw black, not the reference colour), and three's
 * count of live GPU objects is what it was (nothing leaked by the restore), and later changes
 * raise no WebGL warning.
 */

for (const mode of ['table', 'exact'] as const) {
  // A fresh page: the context this test loses and restores would be every later test's.
  const tag = methodReads(mode, 'table') ? [BOTH_BACKENDS] : [];
  test(
    `${mode} mode: after a lost and restored context the bubble redraws itself, table rebuilt, nothing leaked`,
    { tag },
    async ({ page }) => {
      const problems = watchProblems(page);
      await page.setViewportSize({ width: 320, height: 240 });
      await page.goto(`/?field=uniform&thickness=450&env=none&sides=front&animate=0&mode=${mode}`);
      await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
      const expected = reference8({ thicknessNm: 450 });
      expect(worstCodeDifference(await centrePixel(page, false), expected)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
      await openPanel(page);
      const before = await settledGpuObjects(page);

      await loseContext(page);
      // While lost, a change of settings must not throw (nothing can be drawn).
      await page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input').fill('450');
      await restoreContext(page);
      await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
      expect(worstCodeDifference(await centrePixel(page, false), expected), 'centre after restore').toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
      // The plots follow the restored frame in a task of their own: wait for their program too.
      await expect.poll(() => gpuObjects(page)).toEqual(before);
      // A thicker film widens the table: its target is resized, which disposes what the restored
      // context allocated (disposing the lost context's objects would warn).
      await page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input').fill('3000');
      await expect(page).toHaveURL(/thickness=3000/);
      await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
      const thick = reference8({ thicknessNm: 3000 });
      expect(worstCodeDifference(await centrePixel(page, false), thick), 'centre of a thicker film').toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
      expect(problems).toEqual([]);
    },
  );
}

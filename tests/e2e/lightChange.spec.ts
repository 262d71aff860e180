import { expect, test } from '@playwright/test';
import { openPanel } from './panel.ts';
import { reference8, worstCodeDifference } from './referenceColor.ts';
import { expectChangeShownCleanly, recordCentreFrames } from './centreFrames.ts';
import { COARSE_FRAME_CODES } from '../tolerances.ts';

/**
 * A new light through the panel: its spectral transform is computed in a Web Worker while the
 * view goes on drawing, and every frame drawn on the way shows the previous light or the new one
 * (in `table` mode from the coarse table, then in full; in `fourier` mode, which reads the
 * transform per fragment, the previous light until the new one's transform is there), never a
 * blank or mixed one. The centre pixel is the film
 * head-on with nothing behind it, so each light's colour there is the reference's.
 */

const THICKNESS_NM = 450;
const LIGHTS = ['D55', 'D93'] as const;

for (const mode of ['table', 'fourier'] as const)
  test(`${mode} mode: a light change shows the previous light until the new one is drawn, never a frame of another`, async ({ page }) => {
    await page.goto(
      `/?field=uniform&thickness=${THICKNESS_NM}&env=none&sides=front&exposure=1&animate=0&mode=${mode}&illuminant=${LIGHTS[0]}`,
    );
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    const expected = LIGHTS.map((light) => reference8({ thicknessNm: THICKNESS_NM }, light));
    // The two lights' colours are told apart even from a coarse table.
    expect(worstCodeDifference(expected[0]!, expected[1]!)).toBeGreaterThan(2 * COARSE_FRAME_CODES);
    // From here, the centre pixel of every frame the view draws, and whether it was drawn in full.
    const drawn = await recordCentreFrames(page);

    await openPanel(page);
    const illuminant = page.locator('.lil-controller', { hasText: /^illuminant/ }).locator('select');
    for (const [from, to] of [
      [0, 1],
      [1, 0],
    ] as const) {
      await expectChangeShownCleanly(
        drawn,
        () => illuminant.selectOption(LIGHTS[to]),
        [LIGHTS[from], LIGHTS[to]],
        [expected[from]!, expected[to]!],
      );
    }
  });

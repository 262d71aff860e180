import { expect, test } from '@playwright/test';
import { openPanel } from './panel.ts';
import { reference8, worstCodeDifference } from './referenceColor.ts';
import { expectChangeShownCleanly, recordCentreFrames } from './centreFrames.ts';
import { COARSE_FRAME_CODES } from '../tolerances.ts';
import { TABLE_PASS_NAME } from '../../src/film/keptPasses.ts';

/**
 * A change of medium through the panel, to a film whose table rows are computed in a Web Worker
 * (gold inside: dispersive, opaque) and back: every frame drawn on the way shows the previous
 * medium or the new one (the previous table until the rows are there, then the new coarse table,
 * then the full one), never a blank or mixed one; and the way there a second time compiles no
 * table pass (it keeps the programs of its last two sets of defines). The centre pixel is the film head-on with nothing behind it, so
 * each medium's colour there is the reference's.
 */

const THICKNESS_NM = 450;
const INSIDES = ['constant', 'Au'] as const;

test('a change to a metal inside and back shows one medium or the other in every frame, is shown the view once, and the way there again compiles no table pass', async ({
  page,
}) => {
  await page.goto(`/?field=uniform&thickness=${THICKNESS_NM}&env=none&sides=front&exposure=1&animate=0`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const expected = [reference8({ thicknessNm: THICKNESS_NM }), reference8({ thicknessNm: THICKNESS_NM, nInside: 'Au' })];
  expect(worstCodeDifference(expected[0]!, expected[1]!)).toBeGreaterThan(2 * COARSE_FRAME_CODES);
  // From here, the centre pixel of every frame the view draws, and whether it was drawn in full.
  const drawn = await recordCentreFrames(page);
  /** The ids of the table pass's programs three holds now. */
  const programIds = () =>
    page.evaluate(
      (name) =>
        (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView.renderer.info
          .programs!.filter((p) => p.name === name)
          .map((p) => p.id),
      TABLE_PASS_NAME,
    );

  // From here, how many frames the view is shown: a change is resolved into one frame, and the
  // frames that complete its table draw that frame without setting the materials again.
  await page.evaluate(() => {
    const w = window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView; shown: number };
    const show = w.bubbleView.show.bind(w.bubbleView);
    w.shown = 0;
    w.bubbleView.show = (frame) => {
      w.shown++;
      show(frame);
    };
  });
  const framesShown = () => page.evaluate(() => (window as unknown as { shown: number }).shown);

  await openPanel(page);
  const inside = page.locator('.lil-controller', { hasText: /^inside medium/ }).locator('select');
  let programsThere: number[] = [];
  for (const [from, to] of [
    [0, 1],
    [1, 0],
    [0, 1],
  ] as const) {
    const shownBefore = await framesShown();
    await expectChangeShownCleanly(
      drawn,
      () => inside.selectOption(INSIDES[to]),
      [INSIDES[from], INSIDES[to]],
      [expected[from]!, expected[to]!],
    );
    expect(await framesShown(), 'frames the view was shown for the change').toBe(shownBefore + 1);
    const ids = await programIds();
    expect(ids.length, 'the table pass has a program').toBeGreaterThan(0);
    if (programsThere.length === 0) programsThere = ids;
    // Every table pass drawn with since the first way there is one three held then: none compiled anew.
    else
      expect(Math.max(...ids), `programs ${JSON.stringify(ids)} after ${JSON.stringify(programsThere)}`).toBeLessThanOrEqual(
        Math.max(...programsThere),
      );
  }
});

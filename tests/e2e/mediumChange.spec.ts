import { expect, test } from '@playwright/test';
import { openPanel } from './panel.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';
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

test('a change to a metal inside and back shows one medium or the other in every frame, and the way there again compiles no table pass', async ({
  page,
}) => {
  await page.goto(`/?field=uniform&thickness=${THICKNESS_NM}&env=none&sides=front&exposure=1&animate=0`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const expected = [reference8({ thicknessNm: THICKNESS_NM }), reference8({ thicknessNm: THICKNESS_NM, nInside: 'Au' })];
  expect(worstCodeDifference(expected[0]!, expected[1]!)).toBeGreaterThan(2 * COARSE_FRAME_CODES);
  // From here, the centre pixel of every frame the view draws, and whether it was drawn in full.
  await page.evaluate(() => {
    const w = window as unknown as { bubbleView: import('../../src/scene/bubbleView.ts').BubbleView; drawn: [number[], boolean][] };
    const view = w.bubbleView;
    const render = view.render.bind(view);
    w.drawn = [];
    view.render = (quick?: boolean) => {
      render(quick);
      const gl = view.renderer.getContext();
      const pixel = new Uint8Array(4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      w.drawn.push([[pixel[0]!, pixel[1]!, pixel[2]!], !view.coarse]);
    };
  });
  const drawn = () => page.evaluate(() => (window as unknown as { drawn: [number[], boolean][] }).drawn);
  /** The ids of the table pass's programs three holds now. */
  const programIds = () =>
    page.evaluate(
      (name) =>
        (window as unknown as { bubbleView: import('../../src/scene/bubbleView.ts').BubbleView }).bubbleView.renderer.info
          .programs!.filter((p) => p.name === name)
          .map((p) => p.id),
      TABLE_PASS_NAME,
    );

  await openPanel(page);
  const inside = page.locator('.lil-controller', { hasText: /^inside medium/ }).locator('select');
  let programsThere: number[] = [];
  for (const [from, to] of [
    [0, 1],
    [1, 0],
    [0, 1],
  ] as const) {
    const before = (await drawn()).length;
    await inside.selectOption(INSIDES[to]);
    await expect.poll(async () => (await drawn()).slice(before).some(([, full]) => full)).toBe(true);
    const frames = (await drawn()).slice(before);
    const mediumOf = (rgb: number[]) => [from, to].find((i) => worstCodeDifference(rgb, expected[i]!) <= COARSE_FRAME_CODES);
    console.log(
      `${INSIDES[from]} → ${INSIDES[to]}: ${frames.map(([rgb, full]) => `${rgb}${full ? '' : ' (coarse)'}`).join('; ')}; references ${expected[from]} / ${expected[to]}`,
    );
    const media = frames.map(([rgb]) => mediumOf(rgb));
    expect(media, 'every frame shows one of the two media').not.toContain(undefined);
    // The previous medium, then the new one: once shown, the new one stays.
    expect(media.slice(media.indexOf(to))).toEqual(media.slice(media.indexOf(to)).map(() => to));
    const [last, full] = frames.at(-1)!;
    expect(full).toBe(true);
    expect(worstCodeDifference(last, expected[to]!)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
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

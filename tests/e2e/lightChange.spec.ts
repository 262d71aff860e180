import { expect, test } from '@playwright/test';
import { openPanel } from './panel.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';
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

    await openPanel(page);
    const illuminant = page.locator('.lil-controller', { hasText: /^illuminant/ }).locator('select');
    for (const [from, to] of [
      [0, 1],
      [1, 0],
    ] as const) {
      const before = (await drawn()).length;
      await illuminant.selectOption(LIGHTS[to]);
      await expect.poll(async () => (await drawn()).slice(before).some(([, full]) => full)).toBe(true);
      const frames = (await drawn()).slice(before);
      const lightOf = (rgb: number[]) => [from, to].find((i) => worstCodeDifference(rgb, expected[i]!) <= COARSE_FRAME_CODES);
      console.log(
        `${LIGHTS[from]} → ${LIGHTS[to]}: ${frames.map(([rgb, full]) => `${rgb}${full ? '' : ' (coarse)'}`).join('; ')}; references ${expected[from]} / ${expected[to]}`,
      );
      const lights = frames.map(([rgb]) => lightOf(rgb));
      expect(lights, 'every frame shows one of the two lights').not.toContain(undefined);
      // The previous light, then the new one: once shown, the new light stays.
      expect(lights.slice(lights.indexOf(to))).toEqual(lights.slice(lights.indexOf(to)).map(() => to));
      const [last, full] = frames.at(-1)!;
      expect(full).toBe(true);
      expect(worstCodeDifference(last, expected[to]!)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    }
  });

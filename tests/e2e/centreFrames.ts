import { expect, type Page } from '@playwright/test';
import { MAX_CODE_DIFFERENCE, worstCodeDifference } from './referenceColor.ts';
import { COARSE_FRAME_CODES } from '../tolerances.ts';
import { DISPERSIVE_FIRST_FRAME_MS } from './waits.ts';

/** Each frame drawn: its centre pixel (8-bit RGB) and whether it was drawn in full (not from a coarse table). */
export type CentreFrame = [number[], boolean];

/**
 * From now on, records the centre pixel of every frame the page's view draws, and whether it was
 * drawn in full; returns a reader of the frames recorded so far.
 */
export async function recordCentreFrames(page: Page): Promise<() => Promise<CentreFrame[]>> {
  await page.evaluate(() => {
    const w = window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView; drawn: [number[], boolean][] };
    const view = w.bubbleView;
    const render = view.render.bind(view);
    w.drawn = [];
    view.render = (pace) => {
      const drew = render(pace);
      const gl = view.renderer.getContext();
      const pixel = new Uint8Array(4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      w.drawn.push([[pixel[0]!, pixel[1]!, pixel[2]!], !drew.coarse]);
      return drew;
    };
  });
  return () => page.evaluate(() => (window as unknown as { drawn: CentreFrame[] }).drawn);
}

/**
 * Makes a change (`change`) and waits for a frame drawn in full; then every frame drawn since
 * shows the setting before or after it (each `references` colour within COARSE_FRAME_CODES, so
 * from a coarse table too), the new one stays once shown, and the last is in full within
 * MAX_CODE_DIFFERENCE of the new one's reference. `names` label the two in the log.
 */
export async function expectChangeShownCleanly(
  drawn: () => Promise<CentreFrame[]>,
  change: () => Promise<unknown>,
  names: readonly [string, string],
  references: readonly [number[], number[]],
): Promise<void> {
  const before = (await drawn()).length;
  await change();
  // A change to a metal inside or a dispersive film builds its table from dispersive bins, band by band.
  await expect.poll(async () => (await drawn()).slice(before).some(([, full]) => full), { timeout: DISPERSIVE_FIRST_FRAME_MS }).toBe(true);
  const frames = (await drawn()).slice(before);
  console.log(
    `${names[0]} → ${names[1]}: ${frames.map(([rgb, full]) => `${rgb}${full ? '' : ' (coarse)'}`).join('; ')}; references ${references[0]} / ${references[1]}`,
  );
  const shown = frames.map(([rgb]) => [0, 1].find((i) => worstCodeDifference(rgb, references[i]!) <= COARSE_FRAME_CODES));
  expect(shown, 'every frame shows the setting before or after the change').not.toContain(undefined);
  // The previous setting, then the new one: once shown, the new one stays.
  expect(shown.slice(shown.indexOf(1))).toEqual(shown.slice(shown.indexOf(1)).map(() => 1));
  const [last, full] = frames.at(-1)!;
  expect(full).toBe(true);
  expect(worstCodeDifference(last, references[1])).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
}

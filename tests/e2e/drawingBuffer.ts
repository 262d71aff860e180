import type { Page } from '@playwright/test';

/**
 * The demo's centre pixel (8-bit RGB) read from its WebGL drawing buffer. With `draw`, a frame is
 * drawn first in the same task, so the read does not depend on the context keeping its buffer;
 * without, it is what the page itself last drew.
 */
export const centrePixel = (page: Page, draw = true): Promise<number[]> =>
  page.evaluate((drawFirst) => {
    const view = (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView;
    if (drawFirst) view.render();
    const gl = view.renderer.getContext();
    const pixel = new Uint8Array(4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return [pixel[0]!, pixel[1]!, pixel[2]!];
  }, draw);

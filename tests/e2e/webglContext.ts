import type { Page } from '@playwright/test';

/** The demo page's globals these helpers read. */
type Window_ = Window & { bubbleView: import('../../src/view/bubbleView.ts').BubbleView };

/**
 * three's count of the demo view's live GPU objects, once the plots have been drawn (their probe
 * has its own program, made in the task after the first complete frame).
 */
export const settledGpuObjects = async (page: Page) => {
  await page.waitForSelector('.tfb-plots[data-probe]', { state: 'attached' });
  return gpuObjects(page);
};

/** three's count of the demo view's live GPU objects. */
export const gpuObjects = (page: Page) =>
  page.evaluate(() => {
    const { info } = (window as unknown as Window_).bubbleView.renderer;
    return { geometries: info.memory.geometries, textures: info.memory.textures, programs: info.programs?.length ?? 0 };
  });

/**
 * Loses the demo's WebGL context (WEBGL_lose_context) and waits for the loss; `data-frames` is set
 * to `lost`, so the next ready mark is a frame drawn after restoreContext.
 */
export const loseContext = (page: Page): Promise<void> =>
  page.evaluate(async () => {
    const canvas = (window as unknown as Window_).bubbleView.renderer.domElement;
    const extension = canvas.getContext('webgl2')!.getExtension('WEBGL_lose_context')!;
    const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
    // A lost context gives no extensions: keep this one to restore it with.
    Object.assign(window, { loseContextExtension: extension });
    extension.loseContext();
    await lost;
    document.body.dataset.frames = 'lost';
  });

/** Gives the context lost by loseContext back. */
export const restoreContext = (page: Page): Promise<void> =>
  page.evaluate(() => (window as unknown as { loseContextExtension: WEBGL_lose_context }).loseContextExtension.restoreContext());

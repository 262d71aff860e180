/**
 * A time-lapse of the demo: its frames rendered in one browser launch and one page (each frame
 * opened at its view's URL in the same window, waited on until drawn, captured), then encoded as
 * one animation.
 */
import type { RenderCommand } from '../../src/cli/renderOptions.ts';
import type { ChromiumLaunchOptions } from '../chromium.ts';
import { encodeAnimation } from './encodeAnimation.ts';
import { capture, withDemo, withViewPage } from './renderViews.ts';

type TimeLapse = Extract<RenderCommand, { kind: 'timeLapse' }>;

/** The rendered time-lapse: the animation's file, its size in pixels, and how long it took (server started → file encoded). */
export interface RenderedTimeLapse {
  readonly file: Buffer;
  readonly width: number;
  readonly height: number;
  readonly ms: number;
}

export async function renderTimeLapse(lapse: TimeLapse, launch: ChromiumLaunchOptions): Promise<RenderedTimeLapse> {
  const started = performance.now();
  const [first] = lapse.frames;
  if (!first) throw new Error('a time-lapse has at least one frame');
  const pngs = await withDemo(launch, (browser, base) =>
    withViewPage(browser, first, async (page) => {
      const captured: Buffer[] = [];
      for (const frame of lapse.frames) captured.push(await capture(page, base, frame));
      return captured;
    }),
  );
  const { file, width, height } = await encodeAnimation(pngs, lapse.frameMs, lapse.format);
  return { file, width, height, ms: Math.round(performance.now() - started) };
}

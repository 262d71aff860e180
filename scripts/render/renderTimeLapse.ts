/**
 * A time-lapse of the demo: its frames rendered in one browser launch and one page, then encoded as
 * one animation. The first frame is the page opened at its view's URL; each later one is the same
 * view given its later time in place, waited on until drawn in full, and captured. A flowing film
 * then runs on from the frame before rather than from its start: the same fixed steps in the same
 * order, so each frame is the still a fresh load at its time draws, and the work grows with the
 * film time, not with its square.
 */
import type { RenderCommand } from '../../src/cli/renderOptions.ts';
import type { ChromiumLaunchOptions } from '../chromium.ts';
import { encodeAnimation } from './encodeAnimation.ts';
import { capture, captureAtTime, withDemo, withViewPage } from './renderViews.ts';

type TimeLapse = Extract<RenderCommand, { kind: 'timeLapse' }>;

/** The rendered time-lapse: the animation's file, its size in pixels, and how long it took (server started → file encoded). */
export interface RenderedTimeLapse {
  readonly file: Buffer;
  readonly width: number;
  readonly height: number;
  readonly ms: number;
}

/** Renders the time-lapse, `onFrame` told the frames captured so far (0 before the first) as each is. */
export async function renderTimeLapse(
  lapse: TimeLapse,
  launch: ChromiumLaunchOptions,
  onFrame: (captured: number) => void = () => undefined,
): Promise<RenderedTimeLapse> {
  const started = performance.now();
  const [first] = lapse.frames;
  if (!first) throw new Error('a time-lapse has at least one frame');
  const pngs = await withDemo(launch, (browser, base) =>
    withViewPage(browser, first, async (page) => {
      onFrame(0);
      const captured = [await capture(page, base, first)];
      onFrame(captured.length);
      for (const timeSeconds of lapse.timesS.slice(1)) {
        captured.push(await captureAtTime(page, timeSeconds));
        onFrame(captured.length);
      }
      return captured;
    }),
  );
  const { file, width, height } = await encodeAnimation(pngs, lapse.frameMs, lapse.format);
  return { file, width, height, ms: Math.round(performance.now() - started) };
}

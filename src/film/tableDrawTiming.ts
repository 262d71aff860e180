import { FloatType, type WebGLRenderTarget, type WebGLRenderer } from 'three';
import { GpuTimer } from '../gpu/gpuTimer.ts';
import type { PassKind, TableBandBudget } from './tableBandBudget.ts';

/**
 * Runs `pass` into `target` (bound) and waits for it: a 1-pixel read at column `x` before it (the
 * GPU's earlier work done, the frames queued included) and after it; returns when the pass began
 * and its milliseconds.
 */
function syncTimed(renderer: WebGLRenderer, target: WebGLRenderTarget, x: number, pass: () => void): { began: number; ms: number } {
  const pixel = target.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  renderer.readRenderTargetPixels(target, x, 0, 1, 1, pixel);
  const began = performance.now();
  pass();
  renderer.readRenderTargetPixels(target, x, 0, 1, 1, pixel);
  return { began, ms: performance.now() - began };
}

/**
 * Times the table draws of the app's frames for a TableBandBudget: by the GPU's timer where it has
 * one (the result comes frames later, costing no wait), else by waiting for the GPU (`syncTimed`).
 */
export class TableDrawTiming {
  /** Whether the last timed draw was in the app's frame before (not across frames that drew none): the time between is a frame's. */
  private drawsFollow = false;
  /** The GPU's timer (null where it has none; undefined until the first timed draw). */
  private timer: GpuTimer | null | undefined;

  constructor(private readonly budget: TableBandBudget) {}

  /** Reports the draws the GPU's timer has timed since. */
  poll(): void {
    this.timer?.poll();
  }

  /** The app's frames stop drawing the table (it is complete, or waits): the time until the next timed draw is not a frame's. */
  stop(): void {
    this.drawsFollow = false;
  }

  /**
   * How to run a draw of `texels` texels of a `kind` pass into `target` from column `x` in the app's
   * frames (FilmTablePass.draw's `time`): timed, and reported to the budget.
   */
  timed(renderer: WebGLRenderer, kind: PassKind, texels: number, target: WebGLRenderTarget, x: number): (pass: () => void) => void {
    const follows = this.drawsFollow;
    this.drawsFollow = true;
    const report = (began: number, ms: number) => {
      if (!follows) this.budget.idle();
      this.budget.drawn(kind, texels, began, ms);
    };
    this.timer ??= GpuTimer.of(renderer);
    const timer = this.timer;
    return (pass) => {
      if (!timer) {
        const { began, ms } = syncTimed(renderer, target, x, pass);
        return report(began, ms);
      }
      const began = performance.now();
      timer.time(pass, (ms) => report(began, ms));
    };
  }

  /** Forgets the timer (after a lost context: its queries were the lost context's). */
  invalidate(): void {
    this.timer = undefined;
    this.drawsFollow = false;
  }

  dispose(): void {
    this.timer?.drop();
  }
}

import type { WebGLRenderer } from 'three';
import { GpuTimer } from '../gpu/gpuTimer.ts';

/** What an animating frame of a view cost, apart: the simulation's steps and the bubble's draw. */
export interface FrameCostReading {
  /** The simulation's ms in the frame: its latest ms per step measured (the GPU's timer's, known frames later, or waited for) times its steps. */
  readonly simMs: number;
  /** The bubble's draw on the GPU (ms, the latest known), or null where the GPU has no timer. */
  readonly drawMs: number | null;
  /** The steps the simulation took in the frame. */
  readonly steps: number;
}

/**
 * Without a GPU timer, one frame in this many times the simulation by waiting for the GPU before
 * and after it: its calls return before the GPU has done their work, so their CPU time alone
 * tells little.
 */
const WAITED_EVERY = 2;

/**
 * Measures the parts of a view's frames (docs/governor.md#measuring): the simulation's by
 * EXT_disjoint_timer_query_webgl2 where offered (GpuTimer: no stall, results come frames later),
 * else by waiting for the GPU around it in one frame of WAITED_EVERY; the bubble's draw by the
 * timer where offered.
 */
export class FrameCost {
  private timer: GpuTimer | null | undefined;
  private cpuSimMs = 0;
  private steps = 0;
  /** The ms per step of the latest frame timed with steps (by the GPU's timer, or waited for), and the simulation it was of. */
  private msPerStep: number | null = null;
  private measuredOf: unknown = null;
  private frames = 0;
  private gpuDrawMs: number | null = null;

  constructor(private readonly renderer: WebGLRenderer) {}

  /**
   * Runs the simulation's part of a frame (`run` returns the steps it took; `finish` waits for the
   * GPU's work on it); `of` names the simulation (a step measured of another is forgotten).
   */
  simulate(run: () => number, finish: () => void, of: unknown): void {
    this.timer ??= GpuTimer.of(this.renderer);
    if (of !== this.measuredOf) this.msPerStep = null;
    this.measuredOf = of;
    // Without a timer: waited for in one frame of WAITED_EVERY, and until a step is measured.
    const waited = !this.timer && (this.frames++ % WAITED_EVERY === 0 || this.msPerStep === null);
    if (waited) finish();
    const began = performance.now();
    let steps = 0;
    const perStep = (ms: number) => {
      if (steps > 0) this.msPerStep = ms / steps;
    };
    this.time(() => (steps = run()), perStep);
    if (waited) finish();
    this.cpuSimMs = performance.now() - began;
    if (waited) perStep(this.cpuSimMs);
    this.steps = steps;
  }

  /** Runs the bubble's draw. */
  draw(run: () => void): void {
    this.time(run, (ms) => (this.gpuDrawMs = ms));
  }

  /** The last frame's costs (a frame without steps: no simulation's time); the next frame starts from nothing. */
  take(): FrameCostReading {
    const simMs = this.steps > 0 ? (this.msPerStep === null ? this.cpuSimMs : this.msPerStep * this.steps) : 0;
    const reading = { simMs, drawMs: this.gpuDrawMs, steps: this.steps };
    this.cpuSimMs = 0;
    this.steps = 0;
    return reading;
  }

  /** Forgets the timer (after a lost context: its queries were the lost context's). */
  invalidate(): void {
    this.timer = undefined;
  }

  dispose(): void {
    this.timer?.drop();
  }

  private time(run: () => void, done: (ms: number) => void): void {
    this.timer ??= GpuTimer.of(this.renderer);
    this.timer?.poll();
    if (this.timer) this.timer.time(run, done);
    else run();
  }
}

/**
 * A row's views as its frames draw them: the row's own, and where the row takes turns with an
 * earlier model (BenchRowSpec.takesTurnsWith) that model's view of the same film, drawn with each
 * of the row's frames (before it and after it in turn) and timed apart, so that a busy machine's
 * noise hits both alike.
 */
import type { FilmSettings } from '../../../src/settings/filmSettings.ts';
import type { FrameTime } from '../benchRow.ts';
import { median } from '../median.ts';
import type { RowScene } from './rowScene.ts';

/** The pixel each frame reads back. */
const readBack = new Uint8Array(4);

/** Draws the scene's frame and waits for the GPU to finish it: one pixel read back. */
export function drawAndWait({ view }: RowScene): void {
  const gl = view.renderer.getContext();
  view.render();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, readBack);
}

/** Shows `film` in the scene and draws it: ms. */
function timedFrame(scene: RowScene, film: FilmSettings): number {
  const started = performance.now();
  scene.show(film);
  drawAndWait(scene);
  return performance.now() - started;
}

export class RowViews {
  /** The turns' frame times since the last resize. */
  private turnTimes: number[] = [];
  /** Whether the turns' view drew first in the last frame. */
  private turnsFirst = false;

  constructor(
    readonly own: RowScene,
    readonly turns: RowScene | null,
  ) {}

  resize(size: readonly [number, number]): void {
    this.own.view.resize(...size);
    this.turns?.view.resize(...size);
    this.turnTimes = [];
  }

  /** Draws `film` in both views (the turns' time kept), which goes first alternating from frame to frame; the row's frame, ms. */
  frame(film: FilmSettings): number {
    const turns = this.turns;
    if (!turns) return timedFrame(this.own, film);
    this.turnsFirst = !this.turnsFirst;
    if (this.turnsFirst) this.turnTimes.push(timedFrame(turns, film));
    const ownMs = timedFrame(this.own, film);
    if (!this.turnsFirst) this.turnTimes.push(timedFrame(turns, film));
    return ownMs;
  }

  /** The turns' frame at this size, as the row's is timed: the median of its last `count` frames; null without turns. */
  turnFrame(count: number): FrameTime | null {
    return this.turns ? { medianMs: median(this.turnTimes.slice(-count)), count } : null;
  }

  dispose(): void {
    this.own.dispose();
    this.turns?.dispose();
  }
}

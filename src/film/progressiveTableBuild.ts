import type { WebGLRenderTarget, WebGLRenderer } from 'three';
import type { FilmOptics } from '../settings/filmSettings.ts';
import { filmFill } from '../methods/filmFills.ts';
import type { FilmTableGrid } from './filmTableGrid.ts';
import type { FilmTablePass, TableColumns } from './filmTablePass.ts';
import { TableDrawTiming } from './tableDrawTiming.ts';
import { type PassKind, TableBandBudget } from './tableBandBudget.ts';

/** Each fill's pass is timed apart: its cost per texel differs by orders of magnitude. */
const passKind = (s: FilmOptics): PassKind => filmFill(s);

/**
 * The table built across the app's frames: for new settings a coarse grid (at most 1/16 of the
 * texels) drawn at once, so the next frame shows the change, then the full grid band by band,
 * one band per frame, while the coarse one is shown. Bands and the coarse grid are sized by the
 * pass's measured cost so that each fits in a share of a frame (TableBandBudget).
 */
export class ProgressiveTableBuild {
  private readonly budget = new TableBandBudget();
  private readonly timing = new TableDrawTiming(this.budget);
  /** The full grid being built behind a coarse one: its settings and the columns done. */
  private building: { readonly s: FilmOptics; readonly grid: FilmTableGrid; columns: number } | null = null;

  constructor(private readonly pass: FilmTablePass) {}

  /** Takes the timings the GPU has reported since. */
  poll(): void {
    this.timing.poll();
  }

  /** Stops: a table is built at once instead, or the frames draw none meanwhile. */
  stop(): void {
    this.building = null;
    this.timing.stop();
  }

  /**
   * Starts building `s` over thicknesses up to `maxThicknessNm`: draws its coarse grid into `target` and returns it; or, if `mayWait` and
   * what Web Workers compute for it (the light's transform, a dispersive film's row terms for both
   * grids) is not at hand yet, draws nothing and returns null.
   */
  begin(renderer: WebGLRenderer, s: FilmOptics, maxThicknessNm: number, target: WebGLRenderTarget, mayWait: boolean): FilmTableGrid | null {
    const full = this.pass.fullGrid(s, maxThicknessNm);
    const divisor = this.budget.coarseDivisor(passKind(s), full.width * 2 * full.rows);
    const grid = {
      width: Math.max(2, Math.ceil(full.width / divisor)),
      rows: Math.max(2, Math.ceil(full.rows / divisor)),
      maxThicknessNm: full.maxThicknessNm,
    };
    if (mayWait && !this.pass.inputsReady(s, [grid, full])) {
      this.timing.stop(); // the frames meanwhile draw no table: they are not timed
      return null;
    }
    this.building = { s, grid: full, columns: 0 };
    this.draw(renderer, s, target, grid, [0, grid.width]);
    return grid;
  }

  /** Draws the next band of the full grid being built into `target`; returns that grid once complete, else null. */
  nextBand(renderer: WebGLRenderer, target: WebGLRenderTarget): FilmTableGrid | null {
    const b = this.building;
    if (!b) return null;
    const from = b.columns;
    b.columns += this.budget.bandColumns(passKind(b.s), 2 * b.grid.rows, b.grid.width, b.grid.width - from);
    const last = b.columns === b.grid.width;
    if (last) this.building = null;
    this.draw(renderer, b.s, target, b.grid, [from, b.columns]);
    if (!last) return null;
    this.pass.releaseLight();
    this.timing.stop();
    return b.grid;
  }

  private draw(renderer: WebGLRenderer, s: FilmOptics, target: WebGLRenderTarget, grid: FilmTableGrid, columns: TableColumns): void {
    const texels = (columns[1] - columns[0]) * 2 * grid.rows;
    this.pass.draw(renderer, s, target, grid, [columns], this.timing.timed(renderer, passKind(s), texels, target, columns[0]));
  }

  /** Forgets the build and the GPU's timer (after a lost context). */
  invalidate(): void {
    this.building = null;
    this.timing.invalidate();
  }

  dispose(): void {
    this.timing.dispose();
  }
}

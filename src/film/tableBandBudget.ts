import type { FilmFill } from '../methods/filmFills.ts';

/**
 * How much of the table a frame may build: a full table built behind a coarse one
 * (ProgressiveTableBuild) is drawn in bands of columns, one per frame, each sized by the measured
 * cost of the pass so that it takes at most BAND_SHARE of a frame's own time; the coarse table is
 * sized the same way.
 */

/** A band may take this share of a frame's own time: a frame with a band lasts ≤ 1.5 frames, with room below 2 for the display's vsync and a busy CPU. */
export const BAND_SHARE = 0.5;
/** Until a frame has been measured, a coarse table has this many times fewer texels per side than the full one. */
export const COARSE_DIVISOR = 4;
/** … and the first band of a kind of pass not yet measured is this share of the width. */
const FIRST_BAND_SHARE = 1 / 16;
/**
 * The estimates err on the side of smaller bands. A frame's time measured longer than the one
 * taken counts half (their mean), and at most this many times the one taken: a frame that came late
 * (the page was hidden, a long task ran) does not make the next band a whole table; a shorter one
 * counts at once. A pass's cost per texel measured higher counts at once, a lower one half.
 */
const FRAME_GROWTH = 2;
/** A band is at least one column. */
const MIN_BAND_COLUMNS = 1;

/** What is measured of a table pass: a dispersive film's texel sums its bins, a constant film's the series, a stack's its recursion per bin. */
export type PassKind = FilmFill;

/**
 * A kind of pass not yet measured is taken to cost another kind's measured cost per texel times
 * the ratio of these weights, and twice that to err on the side of smaller bands: a dispersive
 * texel sums 150 bins with their terms read per bin (measured per texel on SwiftShader in the built
 * demo's bands: 4–10× a constant film's), so the estimate, 10×, covers the measured range. A
 * stack's texel runs the recursion over its films in each of 150 bins, two Fresnel interfaces per
 * layer: a 16-layer stack's is taken as 8 dispersive texels (its measured cost replaces it at once).
 */
const KIND_COST: Readonly<Record<PassKind, number>> = { constant: 1, dispersive: 5, stack: 40 };
const UNMEASURED_MARGIN = 2;

export class TableBandBudget {
  /** A frame's own time (ms): the time between table draws in the app's frames, less the draws' own. */
  private frameMs: number | undefined;
  /** The pass's cost per texel (ms), by kind. */
  private readonly msPerTexel = new Map<PassKind, number>();
  /** The app's frames building since they last stopped: when the first draw began, how many were drawn, and all their milliseconds. */
  private run: { firstBegan: number; draws: number; drawnMs: number } | null = null;

  /**
   * A table draw in the app's frames, reported in the order drawn: asked for at `began`
   * (performance.now()), it took `ms` on the GPU for `texels` texels. Where a GPU timer reports it
   * frames later, the CPU may have run ahead of the GPU or waited for it at any one draw; over the
   * draws since the frames started building, the time between them is a frame's own time plus the
   * draws' own (timed by waiting for the GPU, `began` is once its earlier work is done: the same holds).
   */
  drawn(kind: PassKind, texels: number, began: number, ms: number): void {
    if (this.run) {
      const frame = (began - this.run.firstBegan - this.run.drawnMs) / this.run.draws;
      const taken = this.frameMs;
      if (frame > 0) this.frameMs = taken === undefined || frame <= taken ? frame : Math.min((taken + frame) / 2, FRAME_GROWTH * taken);
      this.run.draws++;
      this.run.drawnMs += ms;
    } else this.run = { firstBegan: began, draws: 1, drawnMs: ms };
    // A draw timed at 0 ms (a timer's resolution) tells nothing of the cost.
    if (!(ms > 0 && texels > 0)) return;
    const cost = ms / texels;
    const taken = this.msPerTexel.get(kind);
    this.msPerTexel.set(kind, taken === undefined || cost >= taken ? cost : (taken + cost) / 2);
  }

  /** The app's frames stopped building (the table is complete, or waits): the time until the next draw is not a frame's. */
  idle(): void {
    this.run = null;
  }

  /** The pass's cost per texel: measured, or estimated from another kind's (KIND_COST), or unknown. */
  private cost(kind: PassKind): number | undefined {
    const measured = this.msPerTexel.get(kind);
    if (measured !== undefined) return measured;
    const [other, known] = [...this.msPerTexel][0] ?? [];
    return other === undefined || known === undefined ? undefined : (UNMEASURED_MARGIN * known * KIND_COST[kind]) / KIND_COST[other];
  }

  /** The columns of the next band, `rows` texels each, of the `remaining` columns of a table `width` wide. */
  bandColumns(kind: PassKind, rows: number, width: number, remaining: number): number {
    const cost = this.cost(kind);
    const columns =
      cost === undefined || this.frameMs === undefined
        ? Math.ceil(width * FIRST_BAND_SHARE)
        : Math.floor((BAND_SHARE * this.frameMs) / (cost * rows));
    return Math.min(remaining, Math.max(MIN_BAND_COLUMNS, columns));
  }

  /** How many times fewer texels per side the coarse table has than the full one (`texels` texels). */
  coarseDivisor(kind: PassKind, texels: number): number {
    const cost = this.cost(kind);
    if (cost === undefined || this.frameMs === undefined) return COARSE_DIVISOR;
    return Math.max(COARSE_DIVISOR, Math.ceil(Math.sqrt((texels * cost) / (BAND_SHARE * this.frameMs))));
  }
}

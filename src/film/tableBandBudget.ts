/**
 * How much of the table a frame may build: a full table built behind a coarse one (FilmTable) is
 * drawn in bands of columns, one per frame, each sized by the measured cost of the pass so that it
 * takes at most BAND_SHARE of a frame's own time; the coarse table is sized the same way.
 */

/** A band may take this share of a frame's own time: a frame with a band lasts ≤ 1.75 frames. */
export const BAND_SHARE = 0.75;
/** Until a frame has been measured, a coarse table has this many times fewer texels per side than the full one. */
export const COARSE_DIVISOR = 4;
/** … and the first band of a kind of pass not yet measured is this share of the width. */
const FIRST_BAND_SHARE = 1 / 16;
/**
 * A frame's time is taken as at most this many times the last one measured: a frame that came
 * late (the page was hidden, a long task ran) does not make the next band a whole table.
 */
const FRAME_GROWTH = 2;
/** A band is at least this many columns: the fixed cost of a draw and its sync is then small beside its texels'. */
const MIN_BAND_COLUMNS = 4;

/** What is measured of a table pass: a dispersive film's texel sums its bins, a constant film's the series. */
export type PassKind = 'dispersive' | 'constant';

export class TableBandBudget {
  /** A frame's own time (ms): from the end of one table draw to the next, less that draw. */
  private frameMs: number | null = null;
  /** The pass's measured cost per texel (ms), by kind. */
  private readonly msPerTexel = new Map<PassKind, number>();
  /** When the last table draw of the app's frames ended (performance.now()). */
  private lastDrawEnd: number | null = null;

  /** A frame of the app begins (before its table draw, if any): the time since the last draw is a frame's. */
  frameBegins(now: number): void {
    if (this.lastDrawEnd === null) return;
    const measured = now - this.lastDrawEnd;
    this.frameMs = this.frameMs === null ? measured : Math.min(measured, FRAME_GROWTH * this.frameMs);
  }

  /** A table draw of `texels` texels took `ms` (synced), ending `now`. */
  drawn(kind: PassKind, texels: number, ms: number, now: number): void {
    this.msPerTexel.set(kind, ms / texels);
    this.lastDrawEnd = now;
  }

  /** The app's frames stopped building (the table is complete): the next frame's time is not a frame's. */
  idle(): void {
    this.lastDrawEnd = null;
  }

  /** The columns of the next band, `rows` texels each, of the `remaining` columns of a table `width` wide. */
  bandColumns(kind: PassKind, rows: number, width: number, remaining: number): number {
    const cost = this.msPerTexel.get(kind);
    const columns =
      cost === undefined || this.frameMs === null
        ? Math.ceil(width * FIRST_BAND_SHARE)
        : Math.floor((BAND_SHARE * this.frameMs) / (cost * rows));
    return Math.min(remaining, Math.max(MIN_BAND_COLUMNS, columns));
  }

  /** How many times fewer texels per side the coarse table has than the full one (`texels` texels). */
  coarseDivisor(kind: PassKind, texels: number): number {
    const cost = this.msPerTexel.get(kind);
    if (cost === undefined || this.frameMs === null) return COARSE_DIVISOR;
    return Math.max(COARSE_DIVISOR, Math.ceil(Math.sqrt((texels * cost) / (BAND_SHARE * this.frameMs))));
  }
}

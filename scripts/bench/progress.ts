/**
 * The benchmark's progress: its stages (the reference, each row, the material, the builds, the
 * demo page) with their expected relative cost, and the time left estimated from the stages done.
 */
import type { BenchRow } from './rows.ts';
import { THICKNESS_FIELDS } from '../../src/fields/fields.ts';
import { FILM_METHOD_REGISTRY, methodReads } from '../../src/methods/methods.ts';

export interface Stage {
  readonly name: string;
  /** expected time relative to a fast row's (1) */
  readonly cost: number;
}

/**
 * A row's expected cost against a fast row's, from what its frame computes per fragment, or the
 * flowing film's steps (the full run on SwiftShader: a row whose frame outlasts the budget is
 * trimmed to one frame, so even the slowest stays within a few fast rows).
 */
export function rowCost(row: BenchRow): number {
  // A row whose film evolves steps its simulation each frame: the flow rows, grid 32 to 128, took 1.3–3 times the floor's time in a full run.
  if (THICKNESS_FIELDS[row.settings.field].evolves) return 2;
  const dispersive = typeof row.settings.nFilm !== 'number';
  const mode = row.settings.mode;
  // A bubble row builds its table at the start: by bins, that build weighs like a slower frame.
  if (row.kind === 'bubble' && methodReads(mode, 'table') && (row.quality.table.fill === 'binned' || dispersive)) return 2;
  const cost = FILM_METHOD_REGISTRY[mode].frameCost;
  return dispersive ? cost.dispersive : cost.constant;
}

/** Seconds left: the seconds per unit of cost of the stages done, times the cost of those left. */
export function secondsLeft(done: readonly { readonly cost: number; readonly seconds: number }[], costLeft: number): number | null {
  const cost = done.reduce((sum, d) => sum + d.cost, 0);
  if (cost === 0) return null;
  return (done.reduce((sum, d) => sum + d.seconds, 0) / cost) * costLeft;
}

/** Tracks the stages as they end and prints a line per stage (stderr): its time and the time left. */
export class Progress {
  private readonly done: { cost: number; seconds: number }[] = [];
  private readonly started = performance.now();

  constructor(private readonly stages: readonly Stage[]) {}

  /** Runs a stage, then prints how long it took and about how long the rest will. */
  async run<T>(index: number, work: () => Promise<T> | T): Promise<T> {
    const stage = this.stages[index]!;
    const t0 = performance.now();
    try {
      return await work();
    } finally {
      const seconds = (performance.now() - t0) / 1000;
      this.done.push({ cost: stage.cost, seconds });
      // The stages not yet done, whether started or not (several may run at once).
      const costLeft = this.stages.reduce((sum, s) => sum + s.cost, 0) - this.done.reduce((sum, d) => sum + d.cost, 0);
      const left = secondsLeft(this.done, costLeft);
      const elapsed = (performance.now() - this.started) / 1000;
      console.error(
        `[bench ${elapsed.toFixed(0)} s] ${this.done.length}/${this.stages.length} ${stage.name}: ${seconds.toFixed(1)} s; about ${left === null ? '?' : left.toFixed(0)} s left`,
      );
    }
  }
}

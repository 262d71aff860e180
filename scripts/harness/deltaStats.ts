/** Max, 99th percentile and mean of a list of colour differences (the parity spec and the benchmark report these). */
export interface DeltaStats {
  readonly cases: number;
  readonly max: number;
  readonly p99: number;
  readonly mean: number;
}

export function deltaStats(deltas: readonly number[]): DeltaStats {
  const sorted = [...deltas].sort((a, b) => a - b);
  return {
    cases: deltas.length,
    max: sorted[sorted.length - 1]!,
    p99: sorted[Math.min(sorted.length - 1, Math.floor(0.99 * sorted.length))]!,
    mean: deltas.reduce((s, d) => s + d, 0) / deltas.length,
  };
}

/** The median of timings (the upper one of an even count): the figure the benchmark quotes of repeated measures on a noisy machine. */
export const median = (xs: readonly number[]): number => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;

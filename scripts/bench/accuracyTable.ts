/**
 * The README's table of accuracy against cost, from a full benchmark run: each method at its
 * defaults and three.js's iridescence, their worst ΔE00 on the two error grids and their frame
 * at the run's first size against the plain textured sphere's.
 */
import { DEFAULT_FILM_QUALITY } from '../../src/settings/filmQuality.ts';
import type { BenchResults } from './benchResults.ts';
import { type BenchRow, DEFAULT_TABLE_ROW, EXACT_ROW, FOURIER_ROW, THREE_IRIDESCENCE_ROW } from './rows.ts';

const QUOTED: readonly (readonly [string, string, BenchRow])[] = [
  ['`table` (default)', 'one filtered lookup in a table the GPU fills from the Airy series', DEFAULT_TABLE_ROW],
  ['`fourier`', 'the Airy sum as a Fourier series per fragment', FOURIER_ROW],
  ['`exact`', `the binned spectral integral per fragment, ${DEFAULT_FILM_QUALITY.exactSpectralBins} bins`, EXACT_ROW],
  ["three.js's iridescence, for comparison", "two orders, Schlick's Fresnel, fitted CMFs", THREE_IRIDESCENCE_ROW],
];

const ratio = (x: number) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
const worst = (x: number) => (x >= 10 ? x.toFixed(1) : x.toFixed(2));

export function accuracyTableMarkdown(results: BenchResults): string {
  const [width, height] = results.plan.sizes[0]!;
  const floor = results.rows[0]!.frames[0]!.medianMs;
  const lines = QUOTED.map(([mode, how, row]) => {
    const r = results.rows.find((m) => m.name === row.name);
    if (!r || !r.errors || !r.frames[0]) throw new Error(`the run has no frame or error figures for ${row.name}`);
    return `| ${mode} | ${how} | ${worst(r.errors[0]!.max)} | ${worst(r.errors[1]!.max)} | ${ratio(r.frames[0].medianMs / floor)}× |`;
  });
  return [
    `| \`mode\` | how | fixed grid ΔE00 max | stress grid ΔE00 max | frame at ${width}×${height} (× a plain textured sphere) |`,
    '|---|---|---|---|---|',
    ...lines,
  ].join('\n');
}

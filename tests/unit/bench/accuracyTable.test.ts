/**
 * The README's accuracy table quotes a run's figures: the quoted rows' worst ΔE00 on each grid and
 * their frame over the floor's at the first size, here from made-up results with known ratios.
 */
import { describe, expect, it } from 'vitest';
import { accuracyTableMarkdown } from '../../../scripts/bench/accuracyTable.ts';
import type { BenchResults } from '../../../scripts/bench/benchResults.ts';
import { DEFAULT_TABLE_ROW, EXACT_ROW, FOURIER_ROW, ROWS, THREE_IRIDESCENCE_ROW } from '../../../scripts/bench/rows.ts';
import { FULL_PLAN } from '../../../scripts/bench/benchPlan.ts';

const stats = (max: number) => ({ cases: 1, max, p99: max, mean: max });
const row = (name: string, medianMs: number, fixed: number | null, stress = 0) => ({
  name,
  frames: [{ medianMs, count: 20 }],
  errors: fixed === null ? null : [stats(fixed), stats(stress)],
});

describe('the README accuracy table', () => {
  it('quotes each method’s worst ΔE00 per grid and its frame over the floor’s', () => {
    const results = {
      plan: FULL_PLAN,
      rows: [
        row(ROWS[0]!.name, 10, null),
        row(DEFAULT_TABLE_ROW.name, 15, 0.1234, 0.4567),
        row(FOURIER_ROW.name, 250, 0.04, 0.35),
        row(EXACT_ROW.name, 1830, 0.12, 0.71),
        row(THREE_IRIDESCENCE_ROW.name, 18, 93.61, 99.84),
      ],
    } as unknown as BenchResults;
    const lines = accuracyTableMarkdown(results).split('\n');
    expect(lines[0]).toContain('frame at 1280×720');
    expect(lines[2]).toMatch(/^\| `table` \(default\) \| .* \| 0\.12 \| 0\.46 \| 1\.50× \|$/);
    expect(lines[3]).toMatch(/^\| `fourier` \| .* \| 0\.04 \| 0\.35 \| 25\.0× \|$/);
    expect(lines[4]).toMatch(/^\| `exact` \| .*90 bins \| 0\.12 \| 0\.71 \| 183× \|$/);
    expect(lines[5]).toMatch(/^\| three\.js's iridescence, for comparison \| .* \| 93\.6 \| 99\.8 \| 1\.80× \|$/);
  });

  it('refuses a run without a quoted row’s figures', () => {
    const results = { plan: FULL_PLAN, rows: [row(ROWS[0]!.name, 10, null)] } as unknown as BenchResults;
    expect(() => accuracyTableMarkdown(results)).toThrow(DEFAULT_TABLE_ROW.name);
  });
});

import { BOTH_BACKENDS, expect, test } from './fixtures.ts';
import { FIXED_GRID, STRESS_GRID, filmsGridError, referenceXyz } from '../../scripts/bench/errorGrids.ts';
import { MAX_DELTA_E00_MATERIAL_FIXED, MAX_DELTA_E00_MATERIAL_STRESS } from '../tolerances.ts';
import type { ParityGroup } from '../../scripts/harness/parityCase.ts';

/**
 * The whole spectral material (the film in three's MeshPhysicalMaterial, its lobe and the F0 the
 * film is solved into included) over the benchmark's fixed grid (0–2000 nm × 0–85°, 3618 films)
 * and stress grid (0–20 µm × 0–89.9°, 4025 films), a soap film in air: one pixel per film, read
 * from a float target (scripts/harness/materialGrid.ts), against the float64 reference.
 */

type GridPage = Window & { materialGridXyz: (g: ParityGroup, mode: 'table' | 'fourier') => Promise<number[][]> };

// `table` mode, whose figures lie nearest the bounds (`fourier`'s are the benchmark's: docs/benchmarks.md).
for (const mode of ['table'] as const)
  test(
    `${mode} mode: the whole material's pixels are within ΔE00 ${MAX_DELTA_E00_MATERIAL_FIXED} of the reference on the fixed grid and ${MAX_DELTA_E00_MATERIAL_STRESS} on the stress grid`,
    { tag: BOTH_BACKENDS },
    async ({ page }) => {
      await page.goto('/scripts/harness/materialGrid.html');
      await expect(page.locator('body')).toHaveAttribute('data-ready', 'yes');
      for (const [name, grid, bound] of [
        ['fixed', FIXED_GRID, MAX_DELTA_E00_MATERIAL_FIXED],
        ['stress', STRESS_GRID, MAX_DELTA_E00_MATERIAL_STRESS],
      ] as const) {
        const xyz = await page.evaluate(([g, m]) => (window as unknown as GridPage).materialGridXyz(g, m), [grid, mode] as const);
        const e = filmsGridError(grid, referenceXyz(grid), xyz);
        console.log(`material ${mode}, ${name} grid: ΔE00 max ${e.max.toFixed(3)} p99 ${e.p99.toFixed(3)} at ${JSON.stringify(e.worst)}`);
        expect(e.max, `${name} grid, worst at ${JSON.stringify(e.worst)}`).toBeLessThanOrEqual(bound);
      }
    },
  );

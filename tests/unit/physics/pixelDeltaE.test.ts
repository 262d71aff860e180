import { differenceCiede2000, type Rgb } from 'culori';
import { describe, expect, it } from 'vitest';
import { pixelDeltaE00 } from '../../../src/physics/pixelDeltaE.ts';
import { mulberry32 } from '../../seededRandom.ts';
import { CULORI_DE00, ROUNDING_TOL } from '../../tolerances.ts';

/** culori's CIEDE2000 on its own sRGB → Lab path (D65, its own matrices), against ours. */
const culoriDeltaE = differenceCiede2000();
const asCulori = (p: readonly number[]): Rgb => ({ mode: 'rgb', r: p[0]! / 255, g: p[1]! / 255, b: p[2]! / 255 });

describe('pixelDeltaE00 (the example page readout)', () => {
  it('is 0 for equal pixels and symmetric', () => {
    expect(pixelDeltaE00([12, 200, 77], [12, 200, 77])).toBe(0);
    expect(Math.abs(pixelDeltaE00([12, 200, 77], [40, 90, 10]) - pixelDeltaE00([40, 90, 10], [12, 200, 77]))).toBeLessThan(ROUNDING_TOL);
  });
  it("matches culori's CIEDE2000 of the same sRGB pixels", () => {
    const next = mulberry32(19);
    const pixel = () => [0, 1, 2].map(() => Math.floor(256 * next()));
    for (let i = 0; i < 200; i++) {
      const a = pixel();
      const b = pixel();
      expect(Math.abs(pixelDeltaE00(a, b) - culoriDeltaE(asCulori(a), asCulori(b)))).toBeLessThan(CULORI_DE00);
    }
  });
});

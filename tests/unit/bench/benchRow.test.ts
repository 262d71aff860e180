import { describe, expect, it } from 'vitest';
import { fitSizes, fittedFrameMs } from '../../../scripts/bench/benchRow.ts';
import { ALGEBRAIC_TOL } from '../../tolerances.ts';

describe('a slow row’s fitted frame time', () => {
  it('is exact for a frame that costs a fixed time plus a time per pixel', () => {
    const frameMs = (pixels: number) => 40 + 0.09 * pixels;
    const at = (p: number) => [p, frameMs(p)] as const;
    const points = [at(320 * 180), at(640 * 360)] as const;
    expect(Math.abs(fittedFrameMs(points, 1280 * 720) / frameMs(1280 * 720) - 1)).toBeLessThan(ALGEBRAIC_TOL);
  });

  it('is never below the larger frame measured, where the larger came out faster (noise)', () => {
    expect(
      fittedFrameMs(
        [
          [100, 50],
          [400, 45],
        ],
        1600,
      ),
    ).toBe(45);
  });

  it('refuses two frames whose pixels do not grow', () => {
    expect(() =>
      fittedFrameMs(
        [
          [400, 50],
          [400, 60],
        ],
        1600,
      ),
    ).toThrow(/pixels/);
  });

  it('fits from a 16th and a quarter of the pixels', () => {
    const [small, larger] = fitSizes([1280, 720]);
    expect(small[0] * small[1] * 16).toBe(1280 * 720);
    expect(larger[0] * larger[1] * 4).toBe(1280 * 720);
  });
});

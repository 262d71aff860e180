import { describe, expect, it } from 'vitest';
import type { Rgb } from '../../../src/physics/colorConversions.ts';
import { toneMap } from '../../../src/bubbleTwins/toneMapping.ts';
import { ALGEBRAIC_TOL, FEW_OPERATIONS_TOL } from '../../tolerances.ts';

const greys = Array.from({ length: 60 }, (_, k) => 2 ** (k / 4 - 10)); // 2^-10 … 2^4.75

describe('tone mapping (CPU twins of three.js AgX and Khronos PBR Neutral)', () => {
  it('none leaves the radiance alone (the caller clips)', () => {
    expect(toneMap([0.2, 3, -0.1], 'none')).toEqual([0.2, 3, -0.1]);
  });

  for (const mapping of ['agx', 'neutral'] as const) {
    it(`${mapping}: every radiance from 2^-10 to 2^4.75 and beyond lands in [0, 1], and brighter grey is never darker`, () => {
      let last = -Infinity;
      for (const g of greys) {
        const out = toneMap([g, g, g], mapping);
        for (const c of out) {
          expect(c).toBeGreaterThanOrEqual(0);
          expect(c).toBeLessThanOrEqual(1);
        }
        expect(out[1]).toBeGreaterThanOrEqual(last);
        last = out[1];
      }
      for (const c of toneMap([1e6, 50, 0], mapping)) expect(Number.isFinite(c) && c >= 0 && c <= 1).toBe(true);
    });
  }

  it('neutral: below the compression start (peak 0.76 after the 0.04 offset) a colour only loses the offset (the Khronos definition)', () => {
    const c: Rgb = [0.5, 0.3, 0.1];
    const out = toneMap(c, 'neutral');
    out.forEach((v, i) => expect(Math.abs(v - (c[i]! - 0.04))).toBeLessThan(FEW_OPERATIONS_TOL));
    // The toe: below 0.08 the offset is x − x²/0.16 of the darkest channel.
    const dark = toneMap([0.05, 0.05, 0.05], 'neutral');
    expect(Math.abs(dark[0] - (0.05 - (0.05 - 0.05 ** 2 / 0.16)))).toBeLessThan(FEW_OPERATIONS_TOL);
  });

  it('neutral: white (1, 1, 1) compresses to 1 − 0.24²/(0.96 + 0.24 − 0.76), grey stays grey', () => {
    const out = toneMap([1, 1, 1], 'neutral');
    const expected = 1 - 0.24 ** 2 / (0.96 + 0.24 - 0.76);
    for (const v of out) expect(Math.abs(v - expected)).toBeLessThan(ALGEBRAIC_TOL);
  });
});

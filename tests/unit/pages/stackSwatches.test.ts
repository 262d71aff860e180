import { describe, expect, it } from 'vitest';
import { SWATCH_ANGLES_DEG, SWATCH_STACKS, coatedLensPercent, stackSwatchRgb8 } from '../../../src/pages/stackSwatches.ts';

describe("the materials page's stacks", () => {
  it('the coated lens reflects 1.26 % at 550 nm where bare crown glass reflects 4.26 % (Macleod; Fresnel at 0°)', () => {
    const { coated, bare } = coatedLensPercent();
    expect(coated.toFixed(2)).toBe('1.26');
    expect(bare.toFixed(2)).toBe('4.26');
  });

  it('every swatch is an 8-bit colour, and nacre changes colour between its two angles', () => {
    for (const name of SWATCH_STACKS)
      for (const angle of SWATCH_ANGLES_DEG)
        for (const v of stackSwatchRgb8(name, angle)) expect(Number.isInteger(v) && v >= 0 && v <= 255).toBe(true);
    const [a, b] = SWATCH_ANGLES_DEG.map((angle) => stackSwatchRgb8('nacre', angle).join());
    expect(a).not.toBe(b);
  });
});

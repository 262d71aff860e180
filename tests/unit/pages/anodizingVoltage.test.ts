import { describe, expect, it } from 'vitest';
import { anodizingText } from '../../../src/pages/anodizingVoltage.ts';

describe('the anodized titanium slider’s label', () => {
  it('gives the voltage as thickness / 2 nm/V and the range 1.6–2.8 nm/V spans, in whole volts', () => {
    // 60 nm: 30 V nominal; 60 / 2.8 = 21.4 → 21 V, 60 / 1.6 = 37.5 → 38 V
    expect(anodizingText(60)).toBe('TiO₂ 60 nm ≈ 30 V (21–38 V for 1.6–2.8 nm/V)');
    // 125 nm: 62.5 → 63 V; 44.6 → 45 V; 78.1 → 78 V
    expect(anodizingText(125)).toBe('TiO₂ 125 nm ≈ 63 V (45–78 V for 1.6–2.8 nm/V)');
  });
});

import { describe, expect, it } from 'vitest';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { filmOptics } from '../../../src/physics/filmReflectance.ts';
import { binnedXyz, significantBins, spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { MAX_SKIP_DE00, TAIL_TOLERANCE } from '../../tolerances.ts';

describe('significantBins: the spectral tails a shader may skip', () => {
  for (const illuminant of ['D55', 'D65', 'D93', 'E', { daylightCct: 4000 }, { daylightCct: 25000 }] as const) {
    it(`moves no film colour by more than ΔE00 ${MAX_SKIP_DE00} under ${JSON.stringify(illuminant)}, black films included`, () => {
      const all = spectralBins(spectralWeights(illuminant), 90);
      const kept = significantBins(all, TAIL_TOLERANCE);
      expect(kept.end - kept.first).toBeLessThan(all.count); // something is skipped
      const white = whiteXyz(illuminant);
      let worst = 0;
      for (const thicknessNm of [0, 5, 10, 50, 120, 300, 550, 900, 1500, 2000, 8000]) {
        for (const angleDeg of [0, 40, 70, 85]) {
          const o = filmOptics({ nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm, angleDeg });
          worst = Math.max(worst, deltaE00(binnedXyz(o, kept), binnedXyz(o, all), white));
        }
      }
      expect(worst).toBeLessThanOrEqual(MAX_SKIP_DE00);
    });
  }

  it('keeps every bin with tolerance 0', () => {
    const all = spectralBins(spectralWeights('D65'), 45);
    expect(significantBins(all, 0)).toMatchObject({ first: 0, end: 45 });
  });
});

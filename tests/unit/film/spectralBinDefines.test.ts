import { describe, expect, it } from 'vitest';
import { significantBins, spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { NAMED_ILLUMINANTS, illuminantLines } from '../../../src/physics/illuminants.ts';
import { NORMALIZATIONS, spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { spectralBinDefines } from '../../../src/film/spectralBinsTexture.ts';

describe('the bins a shader visits do not depend on the light', () => {
  const { exactSpectralBins: count, spectralTailTolerance: tolerance } = DEFAULT_FILM_QUALITY;
  const d = spectralBinDefines(count, tolerance);

  it('cover the significant bins of every offered light with a spectrum (named: daylight, the lamps; daylight every 100 K), both normalisations', () => {
    const illuminants = [
      ...NAMED_ILLUMINANTS.filter((name) => illuminantLines(name) === null),
      ...Array.from({ length: 211 }, (_, i) => ({ daylightCct: 4000 + 100 * i })),
    ];
    expect(illuminants).toContain('LED-V1');
    for (const illuminant of illuminants) {
      for (const normalization of NORMALIZATIONS) {
        const kept = significantBins(spectralBins(spectralWeights(illuminant, normalization), count), tolerance);
        expect(kept.first, JSON.stringify(illuminant)).toBeGreaterThanOrEqual(d.TFC_SPECTRAL_BIN_FIRST!);
        expect(kept.end, JSON.stringify(illuminant)).toBeLessThanOrEqual(d.TFC_SPECTRAL_BIN_END!);
      }
    }
  });

  it("drop of a tinted light at most the tolerance of the untinted light's white, the scale `white` normalises by (the tint's spectrum is at most 1)", () => {
    for (const illuminant of NAMED_ILLUMINANTS.filter((name) => illuminantLines(name) === null)) {
      const white = spectralBins(spectralWeights(illuminant, 'white'), count).weights;
      for (const tint of [
        [1, 0, 0],
        [0, 1, 0],
        [0, 0, 1],
        [1, 0.5, 0.2],
      ] as const) {
        const tinted = spectralBins(spectralWeights(illuminant, 'white', tint), count).weights;
        for (let c = 0; c < 3; c++) {
          let dropped = 0;
          let whole = 0;
          for (let b = 0; b < count; b++) {
            whole += white[3 * b + c]!;
            if (b < d.TFC_SPECTRAL_BIN_FIRST! || b >= d.TFC_SPECTRAL_BIN_END!) dropped += tinted[3 * b + c]!;
          }
          expect(dropped, `${illuminant} ${tint.join()} channel ${c}`).toBeLessThanOrEqual(tolerance * whole);
        }
      }
    }
  });

  it('still skip the far red tail, where the colour-matching functions vanish', () => {
    expect(d.TFC_SPECTRAL_BIN_END).toBeLessThan(count);
  });
});

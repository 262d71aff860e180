import { describe, expect, it } from 'vitest';
import { METHOD_TWINS } from '../../../src/methods/methodTwins.ts';
import { FILM_METHODS } from '../../../src/methods/methods.ts';
import { spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { filmOptics } from '../../../src/physics/filmReflectance.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralTransform } from '../../../src/physics/spectralTransform.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { MAX_DELTA_E00_FIXED } from '../../tolerances.ts';

/** Films in air and on glass, thin to a few µm, normal to steep incidence. */
const FILMS = [
  { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 0, angleDeg: 0 },
  { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 350, angleDeg: 30 },
  { nOutside: 1, nFilm: 1.45, nInside: 1.5, thicknessNm: 1200, angleDeg: 60 },
  { nOutside: 1, nFilm: 2.2, nInside: 1, thicknessNm: 3000, angleDeg: 80 },
] as const;

describe("each method's float64 twin", () => {
  const w = spectralWeights('D65', 'white');
  const light = { bins: spectralBins(w, DEFAULT_FILM_QUALITY.exactSpectralBins), transform: spectralTransform(w) };
  const white = whiteXyz('D65');

  it('is registered for every method, and the methods offered to users all have one', () => {
    expect(Object.keys(METHOD_TWINS).sort()).toEqual([...FILM_METHODS].sort());
    expect(METHOD_TWINS.exact).not.toBeNull();
    expect(METHOD_TWINS.table).not.toBeNull();
    expect(METHOD_TWINS.fourier).not.toBeNull();
  });

  for (const [method, twin] of Object.entries(METHOD_TWINS))
    if (twin)
      it(`${method}: matches the adaptive reference as its shader must (parity's fixed-grid bound)`, () => {
        for (const film of FILMS) {
          const d = deltaE00(twin(filmOptics(film), light), filmXyz(film), white);
          expect(d, JSON.stringify(film)).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
        }
      });
});

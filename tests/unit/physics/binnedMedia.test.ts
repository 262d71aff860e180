/**
 * The shaders' binned twin (src/physics/binnedIntegration.ts) over absorbing media: the limits it
 * must meet, each with an answer from outside the code under test.
 */
import { describe, expect, it } from 'vitest';
import { spectralBins, stackBinnedXyz } from '../../../src/physics/binnedIntegration.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import type { FilmStack } from '../../../src/physics/filmReflectance.ts';
import type { Medium } from '../../../src/physics/medium.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { ALGEBRAIC_TOL } from '../../tolerances.ts';

/** k of 1e-9 moves R by ~1e-9 (dR/dk is O(1)): far below a ΔE00 of 1e-4. */
const SMALL_K = 1e-9;
const SMALL_K_DE00 = 1e-4;
/** The binned method against the reference over metals (as on real films, docs/physics.md#sampling: 0.11 at 90 bins). */
const METAL_BINNED_DE00 = 0.12;

const weights = spectralWeights('D65', 'white');
const bins = spectralBins(weights, DEFAULT_FILM_QUALITY.exactSpectralBins);
const dispersiveBins = spectralBins(weights, DEFAULT_FILM_QUALITY.dispersiveSpectralBins);
const white = whiteXyz('D65');
/** Σ of the bins' weights: the binned XYZ of R ≡ 1. */
const binWhite = [0, 1, 2].map((k) => bins.weights.reduce((s, w, i) => (i % 3 === k ? s + w : s), 0));

/** R of a bare interface from air onto ñ = n + ik, s and p averaged (Born & Wolf's form with q = √(ñ² − sin²θ)), written out here. */
function bareReflectance(n: number, k: number, angleDeg: number): number {
  const s = Math.sin((angleDeg * Math.PI) / 180);
  const c = Math.cos((angleDeg * Math.PI) / 180);
  // ñ² − sin²θ = (n² − k² − s²) + i 2nk; its principal root q = a + ib.
  const re = n * n - k * k - s * s;
  const im = 2 * n * k;
  const mod = Math.hypot(re, im);
  const a = Math.sqrt((mod + re) / 2);
  const b = Math.sqrt((mod - re) / 2);
  const rs = ((c - a) ** 2 + b ** 2) / ((c + a) ** 2 + b ** 2);
  // r_p = (ñ² cos θ − q) / (ñ² cos θ + q), ñ² = (n² − k²) + i 2nk.
  const pr = (n * n - k * k) * c;
  const pi = 2 * n * k * c;
  const rp = ((pr - a) ** 2 + (pi - b) ** 2) / ((pr + a) ** 2 + (pi + b) ** 2);
  return (rs + rp) / 2;
}

describe('the binned method on absorbing media (the shaders’ twin)', () => {
  it('d = 0 on a complex substrate is the bare interface’s R times the white, at 0° and 60°', () => {
    for (const angleDeg of [0, 60]) {
      const xyz = stackBinnedXyz(
        { nOutside: 1, nFilm: 1.5, nInside: { complex: [0.43, 2.455] }, thicknessNm: 0, angleDeg },
        'unpolarized',
        bins,
      );
      const r = bareReflectance(0.43, 2.455, angleDeg);
      xyz.forEach((v, k) => expect(Math.abs(v - r * binWhite[k]!)).toBeLessThan(ALGEBRAIC_TOL));
    }
  });

  it('k = 0 is the real path, and k → 0 tends to it (film and inside)', () => {
    const stack = { nOutside: 1, thicknessNm: 640, angleDeg: 35 };
    const real = stackBinnedXyz({ ...stack, nFilm: 1.38, nInside: 1.7 }, 'unpolarized', bins);
    const zero = stackBinnedXyz({ ...stack, nFilm: { complex: [1.38, 0] }, nInside: { complex: [1.7, 0] } }, 'unpolarized', bins);
    zero.forEach((v, k) => expect(Math.abs(v - real[k]!)).toBeLessThan(ALGEBRAIC_TOL));
    const small = stackBinnedXyz(
      { ...stack, nFilm: { complex: [1.38, SMALL_K] }, nInside: { complex: [1.7, SMALL_K] } },
      'unpolarized',
      bins,
    );
    expect(deltaE00(small, real, white)).toBeLessThan(SMALL_K_DE00);
  });

  it(`stays within ΔE00 ${METAL_BINNED_DE00} of the reference for films on metals and an absorbing film, 0–1000 nm, 0–80°`, () => {
    const stacks: readonly Omit<FilmStack<Medium>, 'thicknessNm' | 'angleDeg'>[] = [
      { nOutside: 1, nFilm: 1.38, nInside: 'Au' },
      { nOutside: 1, nFilm: 'TiO2', nInside: 'Ti' },
      { nOutside: 1, nFilm: 'Fe3O4', nInside: 'Fe' },
      { nOutside: 1, nFilm: { complex: [2.2, 0.3] }, nInside: { complex: [2.6, 3.4] } },
    ];
    for (const stack of stacks)
      for (const thicknessNm of [0, 40, 170, 430, 1000])
        for (const angleDeg of [0, 50, 80]) {
          const film = { ...stack, thicknessNm, angleDeg };
          expect(deltaE00(stackBinnedXyz(film, 'unpolarized', dispersiveBins), filmXyz(film), white), JSON.stringify(film)).toBeLessThan(
            METAL_BINNED_DE00,
          );
        }
  });
});

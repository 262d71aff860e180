import { describe, expect, it } from 'vitest';
import { type Complex, cAbs2, cAdd, cMul } from '../../../src/physics/complex.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { airySeriesConverges, airySeriesTerms, airySeriesXyz, fourierXyz } from '../../../src/physics/airySeries.ts';
import { type FilmStack, SOAP_FILM_IN_AIR, filmOptics, reflectanceAt } from '../../../src/physics/filmReflectance.ts';
import { spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM, spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { spectralTransform } from '../../../src/physics/spectralTransform.ts';
import { IDENTITY_TOL, ROUNDING_TOL, SERIES_DE00, SPECTRAL_TRANSFORM_WHITE_TOL } from '../../tolerances.ts';

const weights = spectralWeights('D65');
const transform = spectralTransform(weights);
const bins = spectralBins(weights, 90);
const white = whiteXyz('D65');

describe('the light’s spectral transform F_j(x) = ∫ w_j e^{i2πx/λ} dλ', () => {
  it('is the white at x = 0: F_j(0) = ∫ w_j dλ = W_j, real', () => {
    for (let j = 0; j < 3; j++) {
      expect(Math.abs(transform.values[j]! - white[j]!)).toBeLessThan(SPECTRAL_TRANSFORM_WHITE_TOL);
      expect(Math.abs(transform.values[3 + j]!)).toBeLessThan(1e-15);
    }
  });

  it('equals a direct λ-quadrature of its definition (0.005 nm trapezoid) at paths from 0.3 to 200 µm', () => {
    const h = 0.005;
    for (const k of [31, 500, 2345, 20_000]) {
      const x = k * transform.stepNm;
      const direct = [0, 0, 0, 0, 0, 0];
      for (let i = 0, n = (LAMBDA_MAX_NM - LAMBDA_MIN_NM) / h; i <= n; i++) {
        const l = LAMBDA_MIN_NM + i * h;
        const u = l - LAMBDA_MIN_NM;
        const i0 = Math.min(Math.floor(u), 449);
        const f = u - i0;
        const e = (i === 0 || i === n ? 0.5 : 1) * h;
        const phase = (2 * Math.PI * x) / l - 2 * Math.PI * transform.carrierPerNm * x; // demodulated, as stored
        [weights.x, weights.y, weights.z].forEach((t, j) => {
          const w = t[i0]! * (1 - f) + t[i0 + 1]! * f;
          direct[j]! += e * w * Math.cos(phase);
          direct[j + 3]! += e * w * Math.sin(phase);
        });
      }
      for (let j = 0; j < 6; j++) expect(Math.abs(transform.values[6 * k + j]! - direct[j]!)).toBeLessThan(2e-5);
    }
  });
});

describe('the Airy sum as a Fourier series', () => {
  it('sums to eq (13)–(14)’s R at any phase: C₀ + 2 Re Σ B q^{m−1} e^{imφ} = |r|²', () => {
    const stacks: FilmStack[] = [
      { ...SOAP_FILM_IN_AIR, thicknessNm: 400, angleDeg: 30 },
      { nOutside: 1, nFilm: 2.5, nInside: 1.5, thicknessNm: 400, angleDeg: 70 },
      { nOutside: 1.5, nFilm: 1.8, nInside: 1, thicknessNm: 400, angleDeg: 60 }, // TIR at b|c: complex q
    ];
    for (const stack of stacks) {
      const optics = filmOptics(stack, 's');
      const t = airySeriesTerms(optics.channels[0]!);
      for (const lambda of [400, 555, 700]) {
        const phi = (2 * Math.PI * optics.opticalPathNm.re) / lambda;
        let sum: Complex = { re: 0, im: 0 };
        let qPower: Complex = { re: 1, im: 0 };
        for (let m = 1; m < 400; m++) {
          sum = cAdd(sum, cMul(qPower, { re: Math.cos(m * phi), im: Math.sin(m * phi) }));
          qPower = cMul(qPower, t.q);
        }
        const r = t.c0 + 2 * cMul(t.b, sum).re;
        expect(Math.abs(r - reflectanceAt(optics, lambda))).toBeLessThan(IDENTITY_TOL);
      }
      expect(cAbs2(t.q)).toBeLessThan(1);
    }
  });

  it('gives the bare interface at thickness 0 (no series terms)', () => {
    const optics = filmOptics({ ...SOAP_FILM_IN_AIR, thicknessNm: 0, angleDeg: 40 });
    const xyz = airySeriesXyz(optics, transform);
    const r = reflectanceAt(optics, 555);
    xyz.forEach((v, j) => expect(Math.abs(v - r * white[j]!)).toBeLessThan(ROUNDING_TOL));
  });

  it(`matches the reference integral within ΔE00 ${SERIES_DE00} over 0–20 µm, 0–89.9°, n 1.33–2.5, every polarisation`, () => {
    let worst = 0;
    let fellBack = 0;
    for (const nFilm of [1.33, 2.5])
      for (const angleDeg of [0, 30, 60, 80, 85, 88, 89, 89.5, 89.9])
        for (const thicknessNm of [0, 0.78, 5, 50, 150, 300, 500, 800, 1200, 2000, 5000, 10_000, 20_000])
          for (const polarization of ['unpolarized', 'paper', 's', 'p'] as const) {
            const stack = { nOutside: 1, nFilm, nInside: 1, thicknessNm, angleDeg };
            const optics = filmOptics(stack, polarization);
            if (!airySeriesConverges(optics, transform)) fellBack++;
            worst = Math.max(worst, deltaE00(fourierXyz(optics, transform, bins), filmXyz(stack, { polarization }), white));
          }
    expect(worst).toBeLessThan(SERIES_DE00);
    expect(fellBack).toBeGreaterThan(0); // the grazing corner is covered by the bins, and tested
  });

  it('truncated as peers do (m ≤ 2, m ≤ 3) it misses what the full series gets: thin films near grazing', () => {
    const stack = { ...SOAP_FILM_IN_AIR, thicknessNm: 300, angleDeg: 80 };
    const optics = filmOptics(stack);
    const reference = filmXyz(stack);
    const full = deltaE00(airySeriesXyz(optics, transform), reference, white);
    for (const orders of [2, 3]) expect(deltaE00(airySeriesXyz(optics, transform, orders), reference, white)).toBeGreaterThan(10 * full);
  });
});

import { describe, expect, it } from 'vitest';
import { xyzToXy } from '../../../src/physics/colorConversions.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { CIE1931_CMF_START_NM, CIE1931_YBAR } from '../../../src/physics/data/cie1931Cmf2deg.ts';
import { C2_CORRECTION, daylightChromaticity, illuminantSpd } from '../../../src/physics/illuminants.ts';
import { filmXyz, integrateXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { CHROMATICITY_TOL, CONVERGENCE_DE00, ROUNDING_TOL, printedValueTol } from '../../tolerances.ts';

describe('XYZ integration, eqs (15)–(18)', () => {
  it('gives a perfect white reflector Y = 1 under the white normalisation', () => {
    for (const il of ['D55', 'D65', 'D93', 'E', 'D65-table', { daylightCct: 12000 }] as const) {
      expect(Math.abs(whiteXyz(il)[1] - 1)).toBeLessThan(ROUNDING_TOL);
    }
  });

  it('puts D65 at the CIE chromaticity x = 0.3127, y = 0.3290 (CIE 015:2018 Table 3), formula and table alike', () => {
    for (const il of ['D65', 'D65-table'] as const) {
      const [x, y] = xyzToXy(whiteXyz(il));
      expect(Math.abs(x - 0.3127)).toBeLessThan(CHROMATICITY_TOL);
      expect(Math.abs(y - 0.329)).toBeLessThan(CHROMATICITY_TOL);
    }
  });

  it('puts D55 at the CIE chromaticity x = 0.33242, y = 0.34743 (CIE 015:2018 Table 3)', () => {
    const [x, y] = xyzToXy(whiteXyz('D55'));
    expect(Math.abs(x - 0.33242)).toBeLessThan(CHROMATICITY_TOL);
    expect(Math.abs(y - 0.34743)).toBeLessThan(CHROMATICITY_TOL);
  });

  it('puts D93 and daylight at any CCT on the CIE daylight locus (CIE 015 eqs 4.7–4.9), from the integrated spectrum', () => {
    for (const [il, cct] of [
      ['D93', 9300 * C2_CORRECTION],
      [{ daylightCct: 4000 }, 4000],
      [{ daylightCct: 25000 }, 25000],
    ] as const) {
      const [x, y] = xyzToXy(whiteXyz(il));
      const locus = daylightChromaticity(cct);
      expect(Math.abs(x - locus.x)).toBeLessThan(CHROMATICITY_TOL);
      expect(Math.abs(y - locus.y)).toBeLessThan(CHROMATICITY_TOL);
    }
  });

  it("puts daylight at D50 and D75's CCTs at CIE 015:2018 Table 3's chromaticities (an independent table)", () => {
    // Nominal 5000 and 7500 K on the current temperature scale (the CCT convention of illuminants.ts).
    for (const [nominalK, x0, y0] of [
      [5000, 0.34567, 0.3585],
      [7500, 0.29902, 0.31485],
    ] as const) {
      const [x, y] = xyzToXy(whiteXyz({ daylightCct: nominalK * C2_CORRECTION }));
      expect(Math.abs(x - x0), `D${nominalK / 100} x`).toBeLessThan(CHROMATICITY_TOL);
      expect(Math.abs(y - y0), `D${nominalK / 100} y`).toBeLessThan(CHROMATICITY_TOL);
    }
  });

  it('puts the equal-energy illuminant E at x = y = 1/3', () => {
    const [x, y] = xyzToXy(whiteXyz('E'));
    expect(Math.abs(x - 1 / 3)).toBeLessThan(CHROMATICITY_TOL);
    expect(Math.abs(y - 1 / 3)).toBeLessThan(CHROMATICITY_TOL);
  });

  it('under the paper normalisation divides by ∫ȳ (= 106.857 over 360–830 nm at 1 nm) with I_in(560) = 1', () => {
    // The CIE's published sum of the 1 nm ȳ table, 360–830 nm.
    expect(Math.abs(CIE1931_YBAR.reduce((a, v) => a + v, 0) - 106.857)).toBeLessThan(printedValueTol(3));
    // The k the paper mode divides by, recovered from its D65 white: Y = ∫ (I/I(560)) ȳ dλ / k.
    const spd = illuminantSpd('D65');
    let integral = 0; // 1 nm sum over the integration's 380–830 nm
    CIE1931_YBAR.forEach((y, i) => {
      const lambda = CIE1931_CMF_START_NM + i;
      if (lambda >= 380) integral += (spd(lambda) / spd(560)) * y;
    });
    const k = integral / whiteXyz('D65', 'paper')[1];
    // ȳ below 380 nm adds < 1e-3, and the two rules of integration differ by less than that.
    expect(Math.abs(k - 106.857)).toBeLessThan(2e-3);
  });

  it('is linear in R: a constant reflectance 0.37 gives 0.37 × the white', () => {
    const w = spectralWeights('D93');
    const got = integrateXyz(() => 0.37, w, 3);
    whiteXyz('D93').forEach((v, i) => expect(Math.abs(got[i]! - 0.37 * v)).toBeLessThan(ROUNDING_TOL));
  });

  it('converges: default sampling is within ΔE00 0.1 of a 0.01 nm step over 0–20 µm, 0–90°, n 1–2.5', () => {
    const white = whiteXyz('D65');
    let worst = 0;
    for (const nFilm of [1, 1.33, 2.5]) {
      for (const thicknessNm of [0, 150, 700, 2500, 9000, 15000, 20000]) {
        for (const angleDeg of [0, 45, 80, 89.9, 90]) {
          const s = { nOutside: 1, nFilm, nInside: 1, thicknessNm, angleDeg };
          worst = Math.max(worst, deltaE00(filmXyz(s, { stepsPerNm: 100 }), filmXyz(s), white));
        }
      }
    }
    expect(worst).toBeLessThan(CONVERGENCE_DE00);
  });
});

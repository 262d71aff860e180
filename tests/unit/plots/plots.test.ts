import { describe, expect, it } from 'vitest';
import { XYZ_TO_LINEAR_SRGB, XYZ_TO_LINEAR_WIDE_GAMUT } from '../../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR, filmReflectance } from '../../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { gamutTriangle, spectralLocus } from '../../../src/plots/chromaticity.ts';
import { filmSpectrum } from '../../../src/plots/filmSpectrum.ts';
import { interferenceScale } from '../../../src/plots/interferenceScale.ts';
import { probeColor } from '../../../src/plots/probeColor.ts';
import { CHROMATICITY_TOL, FEW_OPERATIONS_TOL, PRINTED_MATRIX_XY_TOL, ROUNDING_TOL, WATER_INDEX_TOL } from '../../tolerances.ts';

describe('chromaticity diagram', () => {
  it('the sRGB triangle has the primaries of IEC 61966-2-1 (0.64, 0.33), (0.30, 0.60), (0.15, 0.06)', () => {
    const published = [
      [0.64, 0.33],
      [0.3, 0.6],
      [0.15, 0.06],
    ];
    gamutTriangle(XYZ_TO_LINEAR_SRGB).forEach(([x, y], i) => {
      expect(Math.abs(x - published[i]![0]!)).toBeLessThan(PRINTED_MATRIX_XY_TOL);
      expect(Math.abs(y - published[i]![1]!)).toBeLessThan(PRINTED_MATRIX_XY_TOL);
    });
  });

  it('the Wide Gamut triangle has Adobe Wide Gamut RGB primaries (0.7347, 0.2653), (0.1152, 0.8264), (0.1566, 0.0177)', () => {
    const published = [
      [0.7347, 0.2653],
      [0.1152, 0.8264],
      [0.1566, 0.0177],
    ];
    gamutTriangle(XYZ_TO_LINEAR_WIDE_GAMUT).forEach(([x, y], i) => {
      expect(Math.abs(x - published[i]![0]!)).toBeLessThan(PRINTED_MATRIX_XY_TOL);
      expect(Math.abs(y - published[i]![1]!)).toBeLessThan(PRINTED_MATRIX_XY_TOL);
    });
  });

  it('the spectral locus passes through CIE 015 tabulated points (520 nm: 0.0743, 0.8338; 700 nm: 0.7347, 0.2653)', () => {
    const locus = spectralLocus(380, 700);
    const at = (nm: number) => locus[nm - 380]!;
    expect(Math.abs(at(520)[0] - 0.0743)).toBeLessThan(CHROMATICITY_TOL);
    expect(Math.abs(at(520)[1] - 0.8338)).toBeLessThan(CHROMATICITY_TOL);
    expect(Math.abs(at(700)[0] - 0.7347)).toBeLessThan(CHROMATICITY_TOL);
    expect(Math.abs(at(700)[1] - 0.2653)).toBeLessThan(CHROMATICITY_TOL);
  });
});

describe('spectra at the probe', () => {
  const stack = { ...SOAP_FILM_IN_AIR, thicknessNm: 420, angleDeg: 30 };
  const s = filmSpectrum(stack, 'D65', 'unpolarized');

  it('samples 380–830 nm every nm; R is the reference reflectance; I_in peaks at 1; I_out = R·I_in', () => {
    expect(s.lambdasNm.length).toBe(451);
    expect(s.lambdasNm[0]).toBe(380);
    expect(s.lambdasNm[450]).toBe(830);
    expect(Math.max(...s.incident)).toBe(1);
    for (const i of [0, 100, 175, 450]) {
      expect(Math.abs(s.reflectance[i]! - filmReflectance(s.lambdasNm[i]!, stack))).toBeLessThan(FEW_OPERATIONS_TOL);
      expect(Math.abs(s.reflected[i]! - s.reflectance[i]! * s.incident[i]!)).toBeLessThan(FEW_OPERATIONS_TOL);
    }
  });

  it('a constant index has no n(λ) to plot; water has its own n at each λ and R at that index', () => {
    expect(s.filmIndex).toBeNull();
    const water = filmSpectrum({ ...stack, nFilm: 'water' }, 'D65', 'unpolarized');
    for (const i of [0, 209, 450]) {
      const n = water.filmIndex![i]!;
      // Water at 20 °C (IAPWS 1997): 1.3456 at 380 nm, 1.3334 at 589 nm, 1.3281 at 830 nm.
      expect(Math.abs(n - [1.3456, 1.3334, 1.3281][[0, 209, 450].indexOf(i)]!)).toBeLessThan(WATER_INDEX_TOL);
      const atThatIndex = filmReflectance(water.lambdasNm[i]!, { ...stack, nFilm: n });
      expect(Math.abs(water.reflectance[i]! - atThatIndex)).toBeLessThan(FEW_OPERATIONS_TOL);
    }
  });

  it('the illuminant E is flat: I_in = 1 everywhere, so I_out = R', () => {
    const e = filmSpectrum(stack, 'E', 'unpolarized');
    expect(e.incident.every((v) => v === 1)).toBe(true);
    expect([...e.reflected]).toEqual([...e.reflectance]);
  });
});

describe('interference colour scale', () => {
  const scale = interferenceScale({ ...SOAP_FILM_IN_AIR, angleDeg: 0 }, 1000, 11, {
    illuminant: 'D65',
    polarization: 'unpolarized',
    normalization: 'white',
    xyzToLinearRgb: XYZ_TO_LINEAR_SRGB,
  });

  it('runs from 0 to the maximum in equal steps, each colour the reference film colour', () => {
    expect(scale.map((c) => c.thicknessNm)).toEqual([0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000]);
    expect(scale[4]!.xyz).toEqual(filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, thicknessNm: 400 }));
  });

  it('follows a dispersive film: each colour the dispersive reference colour', () => {
    const water = interferenceScale({ ...SOAP_FILM_IN_AIR, nFilm: 'water', angleDeg: 0 }, 1000, 3, {
      illuminant: 'D65',
      polarization: 'unpolarized',
      normalization: 'white',
      xyzToLinearRgb: XYZ_TO_LINEAR_SRGB,
    });
    expect(water[1]!.xyz).toEqual(filmXyz({ ...SOAP_FILM_IN_AIR, nFilm: 'water', angleDeg: 0, thicknessNm: 500 }));
    expect(water[1]!.xyz).not.toEqual(filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, thicknessNm: 500 }));
  });

  it('a film of no thickness between equal media reflects nothing: black', () => {
    expect(scale[0]!.xyz.every((v) => Math.abs(v) < 1e-15)).toBe(true);
    expect(scale[0]!.rgb8).toEqual([0, 0, 0]);
  });
});

describe('probe colour', () => {
  const stack = { ...SOAP_FILM_IN_AIR, thicknessNm: 450, angleDeg: 20 };
  const light = { illuminant: 'D65', polarization: 'unpolarized', normalization: 'white' } as const;
  const reference = filmXyz(stack, light);

  it('ΔE00 is 0 when the rendered colour is the reference, and grows with a difference', () => {
    expect(Math.abs(probeColor(stack, light, XYZ_TO_LINEAR_SRGB, reference).deltaE00)).toBeLessThan(ROUNDING_TOL);
    const off = probeColor(stack, light, XYZ_TO_LINEAR_SRGB, [reference[0] * 1.1, reference[1], reference[2]]);
    expect(off.deltaE00).toBeGreaterThan(0.5);
  });

  it('the hex is the 8-bit sRGB encoding (IEC 61966-2-1) of the clipped linear RGB', () => {
    const c = probeColor(stack, light, XYZ_TO_LINEAR_SRGB, reference);
    const encode = (v: number) => Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055));
    const expected = c.linearRgb.map((v) => encode(Math.min(1, Math.max(0, v))));
    expect(c.hex).toBe(`#${expected.map((v) => v.toString(16).padStart(2, '0')).join('')}`);
    expect(c.xyz).toEqual(reference);
  });
});

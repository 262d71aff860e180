import { describe, expect, it } from 'vitest';
import {
  D65_XY,
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
  applyMatrix3,
  invert3,
  mapToGamut,
  rgbToXyzMatrix,
  srgbDecode,
  srgbEncode,
} from '../../../src/physics/colorConversions.ts';
import { deltaE00, xyzToLab } from '../../../src/physics/colorDifference.ts';
import {
  ALGEBRAIC_TOL,
  FEW_OPERATIONS_TOL,
  PRINTED_MATRIX_WHITE_TOL,
  ROUNDING_TOL,
  SRGB_KNEE_TOL,
  printedValueTol,
} from '../../tolerances.ts';

describe('colour conversions, eqs (19)–(20) and the display step', () => {
  it("has eq (19) equal to IEC 61966-2-1's matrix except two entries the paper prints differently", () => {
    // IEC 61966-2-1 (sRGB), XYZ → linear RGB, to 4 decimals.
    const iec = [3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.204, 1.057];
    const differing = iec.flatMap((v, i) => (Math.abs(v - XYZ_TO_LINEAR_SRGB[i]!) > 1e-9 ? [i] : []));
    expect(differing).toEqual([2, 3]); // paper: −0.4989 (IEC −0.4986) and −0.9686 (IEC −0.9689)
    // And the matrix derived from the sRGB primaries and D65 agrees with IEC's to its rounding.
    const derived = invert3(rgbToXyzMatrix([0.64, 0.33], [0.3, 0.6], [0.15, 0.06], D65_XY));
    derived.forEach((v, i) => expect(Math.abs(v - iec[i]!)).toBeLessThan(6e-4));
  });

  it('derives the published Display P3 matrix (XYZ → P3 row 1: 2.4934969, −0.9313836, −0.4027108)', () => {
    // Published in e.g. the CSS Color 4 specification's sample code.
    const expected = [
      2.493496911941425, -0.9313836179191239, -0.40271078445071684, -0.8294889695615747, 1.7626640603183463, 0.023624685841943577,
      0.03584583024378447, -0.07617238926804182, 0.9568845240076872,
    ];
    XYZ_TO_LINEAR_DISPLAY_P3.forEach((v, i) => expect(Math.abs(v - expected[i]!)).toBeLessThan(ALGEBRAIC_TOL));
  });

  it('maps the D65 white to R = G = B = 1 in sRGB and Display P3', () => {
    const white = [0.3127 / 0.329, 1, (1 - 0.3127 - 0.329) / 0.329] as const;
    for (const m of [XYZ_TO_LINEAR_SRGB, XYZ_TO_LINEAR_DISPLAY_P3])
      applyMatrix3(m, white).forEach((v) => expect(Math.abs(v - 1)).toBeLessThan(PRINTED_MATRIX_WHITE_TOL));
  });

  it('has an sRGB transfer function that is continuous at its knee and inverted by its decode', () => {
    expect(Math.abs(srgbEncode(0.0031308) - 0.04045)).toBeLessThan(SRGB_KNEE_TOL);
    for (const v of [0, 0.001, 0.2, 0.5, 1]) expect(Math.abs(srgbDecode(srgbEncode(v)) - v)).toBeLessThan(ROUNDING_TOL);
    expect(Math.abs(srgbEncode(0.5) - 0.7353569830524495)).toBeLessThan(FEW_OPERATIONS_TOL); // 1.055·0.5^(1/2.4) − 0.055
  });

  it('clips channel by channel', () => {
    expect(mapToGamut([-0.2, 0.5, 1.4], 0.5)).toEqual([0, 0.5, 1]);
  });

  it('keeps in-gamut colours and, out of gamut, lands in [0, 1] with the chromaticity direction kept (preserve-hue)', () => {
    expect(mapToGamut([0.2, 0.5, 0.9], 0.4, 'preserve-hue')).toEqual([0.2, 0.5, 0.9]);
    const out = mapToGamut([-0.2, 0.5, 1.4], 0.4, 'preserve-hue');
    out.forEach((v) => {
      expect(v).toBeGreaterThanOrEqual(0);
      expect(v).toBeLessThanOrEqual(1);
    });
    // Moving toward grey and scaling keep the ordering of the channels and the ratio of differences.
    const ratio = (c: readonly number[]) => (c[2]! - c[1]!) / (c[1]! - c[0]!);
    expect(Math.abs(ratio(out) - ratio([-0.2, 0.5, 1.4]))).toBeLessThan(ROUNDING_TOL);
  });
});

describe('ΔE00', () => {
  it('reproduces pair 1 of Sharma, Wu & Dalal (2005) Table 1: ΔE00 = 2.0425', () => {
    // Lab (50, 2.6772, −79.7751) vs (50, 0, −82.7485); feed them as XYZ via the inverse CIELAB map.
    const white = [0.95047, 1, 1.08883] as const;
    const fromLab = (l: number, a: number, b: number) => {
      const fy = (l + 16) / 116;
      const inv = (f: number) => (f ** 3 > 216 / 24389 ? f ** 3 : (116 * f - 16) / (24389 / 27));
      return [white[0] * inv(fy + a / 500), white[1] * inv(fy), white[2] * inv(fy - b / 200)] as const;
    };
    const lab = xyzToLab(fromLab(50, 2.6772, -79.7751), white);
    expect(Math.abs(lab.l - 50)).toBeLessThan(ALGEBRAIC_TOL);
    const difference = deltaE00(fromLab(50, 2.6772, -79.7751), fromLab(50, 0, -82.7485), white);
    expect(Math.abs(difference - 2.0425)).toBeLessThan(printedValueTol(4));
  });
});

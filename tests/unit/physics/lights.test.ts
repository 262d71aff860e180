import { describe, expect, it } from 'vitest';
import { xyzToXy } from '../../../src/physics/colorConversions.ts';
import { filmOptics } from '../../../src/physics/filmReflectance.ts';
import {
  ILLUMINANT_EXPECTED,
  NAMED_ILLUMINANTS,
  illuminantFromJson,
  illuminantSpd,
  listedNames,
  parseIlluminant,
} from '../../../src/physics/illuminants.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { spectralTransform } from '../../../src/physics/spectralTransform.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { METHOD_TWINS } from '../../../src/methods/methodTwins.ts';
import { ALGEBRAIC_TOL, LAMP_WHITE_POINT_TOL, ROUNDING_TOL, printedValueTol } from '../../tolerances.ts';

/**
 * CIE 1931 2° colour-matching functions as the CIE's 1 nm table prints them (CIE 015:2018; the
 * 5 nm rows are the 1931 table's), at the wavelengths these tests use.
 */
const CMF_1931: Readonly<Record<number, readonly [number, number, number]>> = {
  500: [0.0049, 0.323, 0.272],
  550: [0.4334499, 0.9949501, 0.008749999],
  588: [1.0090892, 0.781192, 0.001205],
  589: [1.0180064, 0.7691547, 0.001146667],
  600: [1.0622, 0.631, 0.0008],
};

/**
 * CIE 15's published white points (x, y), CIE 1931 2°, of the lamps: FL1–FL12 from CIE 15:2004, the
 * LEDs from CIE 015:2018, as colour-science's chromaticity_coordinates.py carries them (to 4 decimals).
 */
const PUBLISHED_XY: Readonly<Record<string, readonly [number, number]>> = {
  FL1: [0.3131, 0.3371],
  FL2: [0.3721, 0.3751],
  FL3: [0.4091, 0.3941],
  FL4: [0.4402, 0.4031],
  FL5: [0.3138, 0.3452],
  FL6: [0.3779, 0.3882],
  FL7: [0.3129, 0.3292],
  FL8: [0.3458, 0.3586],
  FL9: [0.3741, 0.3727],
  FL10: [0.3458, 0.3588],
  FL11: [0.3805, 0.3769],
  FL12: [0.437, 0.4042],
  'LED-B1': [0.456, 0.4078],
  'LED-B2': [0.4357, 0.4012],
  'LED-B3': [0.3756, 0.3723],
  'LED-B4': [0.3422, 0.3502],
  'LED-B5': [0.3118, 0.3236],
  'LED-BH1': [0.4474, 0.4066],
  'LED-RGB1': [0.4557, 0.4211],
  'LED-V1': [0.4548, 0.4044],
  'LED-V2': [0.3781, 0.3775],
};

/** R of a film between two identical media at normal incidence, eq (13) written out: r1 = (n_a − n_b)/(n_a + n_b), r2 = −r1. */
function normalReflectance(nOut: number, nFilm: number, thicknessNm: number, lambdaNm: number): number {
  const r1 = (nOut - nFilm) / (nOut + nFilm);
  const r2 = -r1;
  const phi = (4 * Math.PI * nFilm * thicknessNm) / lambdaNm;
  const [nr, ni] = [r1 + r2 * Math.cos(phi), r2 * Math.sin(phi)];
  const [dr, di] = [1 + r1 * r2 * Math.cos(phi), r1 * r2 * Math.sin(phi)];
  return (nr * nr + ni * ni) / (dr * dr + di * di);
}

describe('lamps: the CIE fluorescent and LED tables', () => {
  it.each(Object.entries(PUBLISHED_XY))('puts %s at its published white point', (name, [x0, y0]) => {
    const [x, y] = xyzToXy(whiteXyz(parseIlluminant(name)!));
    expect(Math.abs(x - x0)).toBeLessThan(LAMP_WHITE_POINT_TOL);
    expect(Math.abs(y - y0)).toBeLessThan(LAMP_WHITE_POINT_TOL);
  });

  it("holds a table at its end rows' values outside 380–780 nm (FL1's rows: 1.87 at 380, 0.43 at 780)", () => {
    const spd = illuminantSpd('FL1');
    expect(spd(370)).toBe(1.87);
    expect(spd(800)).toBe(0.43);
    expect(spd(830)).toBe(0.43);
    // FL1 at 402.5 nm: halfway between its 400 and 405 nm rows (5.17, 19.49).
    expect(Math.abs(spd(402.5) - (5.17 + 19.49) / 2)).toBeLessThan(ROUNDING_TOL * 100);
  });
});

describe('line sources: summed over their lines', () => {
  it.each([500, 550, 600])(
    'puts line:%i at the chromaticity of the colour-matching functions there, Y = 1 for a perfect reflector',
    (nm) => {
      const [xb, yb, zb] = CMF_1931[nm]!;
      const white = whiteXyz({ lineNm: nm });
      expect(Math.abs(white[0] - xb / yb)).toBeLessThan(printedValueTol(6) / yb);
      expect(Math.abs(white[1] - 1)).toBeLessThan(ROUNDING_TOL);
      expect(Math.abs(white[2] - zb / yb)).toBeLessThan(printedValueTol(6) / yb);
    },
  );

  it("gives a film under a line the film's R at that wavelength times the line's white (analytic, thin and 20 µm thick)", () => {
    for (const [nm, d] of [
      [550, 300],
      [500.5, 20000],
      [632.8, 1234],
    ] as const) {
      const xyz = filmXyz({ nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: d, angleDeg: 0 }, { illuminant: { lineNm: nm } });
      const white = whiteXyz({ lineNm: nm });
      const r = normalReflectance(1, 1.33, d, nm);
      for (let k = 0; k < 3; k++) expect(Math.abs(xyz[k]! - r * white[k]!)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it("puts Na at the sodium D lines' chromaticity: the CIE 1 nm table's 588 and 589 nm rows, interpolated to 588.995 and 589.592 nm, weighted 2 : 1", () => {
    const at = (nm: number): number[] => CMF_1931[588]!.map((v, k) => v + (CMF_1931[589]![k]! - v) * (nm - 588));
    // 589.592 nm lies past the 589 nm row: extrapolating the 588–589 slope would be off, so take 589–590 there.
    const cmf590 = [1.0263, 0.757, 0.0011];
    const d1 = CMF_1931[589]!.map((v, k) => v + (cmf590[k]! - v) * 0.592);
    const sum = at(588.995).map((v, k) => 2 * v + d1[k]!);
    const [x, y] = xyzToXy(whiteXyz('Na'));
    expect(Math.abs(x - sum[0]! / (sum[0]! + sum[1]! + sum[2]!))).toBeLessThan(printedValueTol(6));
    expect(Math.abs(y - sum[1]! / (sum[0]! + sum[1]! + sum[2]!))).toBeLessThan(printedValueTol(6));
  });

  it('lets every method sum the lines: exact, table and fourier twins equal the reference under Na and a line', () => {
    for (const illuminant of ['Na', { lineNm: 450 }] as const) {
      const w = spectralWeights(illuminant);
      const light = { bins: spectralBins(w, 90), transform: spectralTransform(w) };
      for (const [d, angle] of [
        [420, 0],
        [15000, 60],
        [30, 89],
      ] as const) {
        const stack = { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: d, angleDeg: angle };
        const reference = filmXyz(stack, { illuminant });
        for (const twin of [METHOD_TWINS.exact!, METHOD_TWINS.table!, METHOD_TWINS.fourier!]) {
          const xyz = twin(filmOptics(stack, 'unpolarized'), light);
          for (let k = 0; k < 3; k++) expect(Math.abs(xyz[k]! - reference[k]!)).toBeLessThan(1e-9);
        }
      }
    }
  });
});

describe('bad lights: named with the allowed range, nothing computed', () => {
  it.each(['FL13', 'line:379', 'line:780.5', 'line:', 'line:abc', 'na', 'LED-B6'])('refuses %s', (text) => {
    expect(parseIlluminant(text)).toBeNull();
    expect(() => illuminantFromJson(text)).toThrow(ILLUMINANT_EXPECTED);
  });

  it('states the lights and the line range in the message', () => {
    expect(ILLUMINANT_EXPECTED).toContain('FL12');
    expect(ILLUMINANT_EXPECTED).toContain('LED-V2');
    expect(ILLUMINANT_EXPECTED).toContain('Na');
    expect(ILLUMINANT_EXPECTED).toContain('line:NM with NM in [380, 780] nm');
  });

  it('lists the lights with runs of numbered names shortened', () => {
    expect(listedNames(NAMED_ILLUMINANTS)).toBe(
      'D55, D65, D93, E, D65-table, FL1–FL12, LED-B1–LED-B5, LED-BH1, LED-RGB1, LED-V1, LED-V2, Na',
    );
  });

  it('reads the edges of the line range and writes a line back as it reads it', () => {
    expect(parseIlluminant('line:380')).toEqual({ lineNm: 380 });
    expect(parseIlluminant('line:780')).toEqual({ lineNm: 780 });
    expect(illuminantFromJson('line:632.8')).toEqual({ lineNm: 632.8 });
  });

  it('takes a line as the spec it reads as, and refuses one outside [380, 780] nm or with other keys', () => {
    expect(illuminantFromJson({ lineNm: 589 })).toEqual({ lineNm: 589 });
    for (const bad of [{ lineNm: 379.9 }, { lineNm: 781 }, { lineNm: '589' }, { lineNm: 589, daylightCct: 5000 }])
      expect(() => illuminantFromJson(bad)).toThrow(/illuminant: .* line:NM with NM in \[380, 780\] nm/);
  });
});

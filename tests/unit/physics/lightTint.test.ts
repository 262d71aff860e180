/**
 * The tinted light (lightTint.ts; docs/physics.md#a-tinted-light). Expected values come from the
 * published basis's own rows (Mallett and Yuksel 2019, as colour-science carries them), from its
 * defining property (its sum is 1; a perfect reflector under D65 takes the tint's colour), and from
 * the untinted light computed without any tint.
 */
import { describe, expect, it } from 'vitest';
import { applyMatrix3, XYZ_TO_LINEAR_SRGB } from '../../../src/physics/colorConversions.ts';
import { filmOptics } from '../../../src/physics/filmReflectance.ts';
import { tintSpectrum } from '../../../src/physics/illuminants.ts';
import { LIGHT_TINT_EXPECTED, lightTintFromJson, lightTintText, parseLightTint } from '../../../src/physics/lightTint.ts';
import { MALLETT2019_BLUE, MALLETT2019_GREEN, MALLETT2019_RED } from '../../../src/physics/data/mallett2019Basis.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { spectralTransform } from '../../../src/physics/spectralTransform.ts';
import { type SpectralWeights, spectralWeights } from '../../../src/physics/spectralWeights.ts';
import { METHOD_TWINS } from '../../../src/methods/methodTwins.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { ALGEBRAIC_TOL, MALLETT_BASIS_SUM_TOL, TINTED_WHITE_RGB_TOL } from '../../tolerances.ts';

const SOAP = { nOutside: 1, nFilm: 1.33, nInside: 1 } as const;

/** ∫ weights dλ by the trapezoid rule on their 1 nm knots: the XYZ of a perfect reflector. */
const perfectReflector = (w: SpectralWeights): [number, number, number] => {
  const t = (a: Float64Array) => a.reduce((sum, v, i) => sum + v * (i === 0 || i === a.length - 1 ? 0.5 : 1), 0);
  return [t(w.x), t(w.y), t(w.z)];
};

describe("Mallett and Yuksel's basis", () => {
  it('sums to 1 at every published row, within the table as published (it holds 1 to 1e-5)', () => {
    expect(MALLETT2019_RED).toHaveLength(81);
    for (let i = 0; i < 81; i++) {
      expect(Math.abs(MALLETT2019_RED[i]! + MALLETT2019_GREEN[i]! + MALLETT2019_BLUE[i]! - 1)).toBeLessThan(MALLETT_BASIS_SUM_TOL);
    }
  });

  it('is read between rows linearly and held at its end rows outside 380–780 nm (rows 585, 590 nm: red 0.0744, 0.6244)', () => {
    const red = tintSpectrum([1, 0, 0]);
    expect(red(590)).toBe(0.624393724178075);
    expect(Math.abs(red(587.5) - (0.0743560378459411 + 0.624393724178075) / 2)).toBeLessThan(ALGEBRAIC_TOL);
    expect(red(830)).toBe(0.333569513405591);
    expect(red(300)).toBe(0.327457413827055);
  });
});

describe('a tinted light', () => {
  it('tint 1,1,1 gives exactly the untinted light, for a spectrum and a line source, in both normalisations', () => {
    for (const illuminant of ['D65', 'FL2', 'Na', { lineNm: 632.8 }] as const) {
      for (const normalization of ['white', 'paper'] as const) {
        const stack = { ...SOAP, thicknessNm: 420, angleDeg: 30 };
        expect(filmXyz(stack, { illuminant, normalization, lightTint: [1, 1, 1] })).toEqual(filmXyz(stack, { illuminant, normalization }));
      }
    }
  });

  it.each([
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0.5, 0.2],
    [0.3, 0.7, 0.9],
  ] as const)("gives a perfect reflector under D65 tinted %s,%s,%s (white) that colour's linear sRGB", (...tint) => {
    const rgb = applyMatrix3(XYZ_TO_LINEAR_SRGB, perfectReflector(spectralWeights('D65', 'white', tint)));
    for (let k = 0; k < 3; k++) expect(Math.abs(rgb[k]! - tint[k]!)).toBeLessThan(TINTED_WHITE_RGB_TOL);
  });

  it('divides by the untinted Y under `white`: a grey tint g gives Y = g to the basis sum', () => {
    const [, y] = perfectReflector(spectralWeights('FL2', 'white', [0.5, 0.5, 0.5]));
    expect(Math.abs(y - 0.5)).toBeLessThan(MALLETT_BASIS_SUM_TOL);
  });

  it("weights a line source's lines by the tint's spectrum at each line (the basis's rows 585 and 590 nm, linear between)", () => {
    const untinted = spectralWeights('Na', 'white').lines!;
    const tinted = spectralWeights('Na', 'white', [0, 1, 0]).lines!;
    // Green at 585 and 590 nm, as published.
    const green = (nm: number) => 0.913578989551261 + ((0.364348803907687 - 0.913578989551261) * (nm - 585)) / 5;
    untinted.forEach((line, i) => {
      for (const c of ['x', 'y', 'z'] as const) {
        expect(Math.abs(tinted[i]![c] - line[c] * green(line.nm))).toBeLessThan(ALGEBRAIC_TOL * line[c]);
      }
    });
    const laser = spectralWeights({ lineNm: 590 }, 'white', [0, 0, 1]).lines![0]!;
    expect(Math.abs(laser.y / spectralWeights({ lineNm: 590 }).lines![0]!.y - 0.0112574781603901)).toBeLessThan(ALGEBRAIC_TOL);
  });

  it('lets every method follow the tint: exact, table and fourier twins equal the reference under tinted Na', () => {
    const w = spectralWeights('Na', 'white', [1, 0.5, 0.2]);
    const light = { bins: spectralBins(w, 90), transform: spectralTransform(w) };
    for (const [d, angle] of [
      [420, 0],
      [15000, 60],
    ] as const) {
      const stack = { ...SOAP, thicknessNm: d, angleDeg: angle };
      const reference = filmXyz(stack, { illuminant: 'Na', lightTint: [1, 0.5, 0.2] });
      for (const twin of [METHOD_TWINS.exact!, METHOD_TWINS.table!, METHOD_TWINS.fourier!]) {
        const xyz = twin(filmOptics(stack, 'unpolarized'), light);
        for (let k = 0; k < 3; k++) expect(Math.abs(xyz[k]! - reference[k]!)).toBeLessThan(1e-9);
      }
    }
  });
});

describe('bad tints: named with the allowed range, nothing computed', () => {
  it.each(['', '1', '1,1', '1,1,1,1', '1.01,0,0', '0,-0.01,0', '0,0,NaN', '0,,0', '0x1,0,0', 'red'])('refuses the text %j', (text) => {
    expect(parseLightTint(text)).toBeNull();
  });

  it.each([[[1, 1]], [[1, 1, 1, 1]], [[2, 0, 0]], [[0, '0.5', 0]], [[0, null, 0]], ['1,1,1'], [null], [{ r: 1, g: 1, b: 1 }]])(
    'refuses the JSON value %j with a ParameterError naming lightTint and [0, 1]',
    (value) => {
      expect(() => lightTintFromJson(value)).toThrow(ParameterError);
      expect(() => lightTintFromJson(value)).toThrow(/^lightTint: .* expected three numbers R,G,B, each in \[0, 1\]$/);
    },
  );

  it("reads the domain's edges and writes a tint back as it reads it", () => {
    expect(parseLightTint('0,1,0.25')).toEqual([0, 1, 0.25]);
    expect(parseLightTint(lightTintText([1, 0.5, 0.2]))).toEqual([1, 0.5, 0.2]);
    expect(lightTintFromJson([0, 0, 1])).toEqual([0, 0, 1]);
    expect(LIGHT_TINT_EXPECTED).toBe('three numbers R,G,B, each in [0, 1]');
  });
});

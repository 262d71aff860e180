/**
 * A film's reflection of coloured light as a matrix (environmentMatrix.ts). Expected values come
 * from the basis's defining properties (it sums to 1; under D65 a colour's spectrum gives back that
 * colour), from Fresnel's bare interface (R₀ = ((n − 1)/(n + 1))² at every λ), and from the
 * integral's linearity: the film under a tinted light computed without the matrix.
 */
import { describe, expect, it } from 'vitest';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3 } from '../../../src/physics/colorConversions.ts';
import { filmEnvironmentMatrix, reflectedXyz } from '../../../src/physics/environmentMatrix.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { type Medium } from '../../../src/physics/medium.ts';
import { ALGEBRAIC_TOL, MALLETT_BASIS_SUM_TOL, TINTED_WHITE_RGB_TOL } from '../../tolerances.ts';

const film = (nFilm: Medium, nInside: Medium, thicknessNm: number, angleDeg = 0) => ({
  nOutside: 1,
  nFilm,
  nInside,
  thicknessNm,
  angleDeg,
});

describe('the environment matrix M', () => {
  it.each([
    ['a soap film', film(1.33, 1, 420)],
    ['a water film (dispersive) at 40°', film('water', 1, 700, 40)],
    ['a TiO₂ film on titanium', film('TiO2', 'Ti', 120, 10)],
  ])('of %s: M · (1, 1, 1) is the film under the light itself (the basis sums to 1)', (_, stack) => {
    const options = { illuminant: 'FL2', polarization: 's' } as const;
    const white = reflectedXyz(filmEnvironmentMatrix(stack, options), [1, 1, 1]);
    const plain = filmXyz(stack, options);
    for (let k = 0; k < 3; k++) expect(Math.abs(white[k]! - plain[k]!)).toBeLessThan(MALLETT_BASIS_SUM_TOL);
  });

  it.each([
    [film(1.33, 1, 650), [1, 0.5, 0.2]],
    [film('water', 1.5, 1200, 60), [0.3, 0.7, 0.9]],
    [film(2.35, 'Au', 80), [0.9, 0.05, 0.05]],
  ] as const)('%j: M · c is the film under the light tinted c, integrated without M', (stack, c) => {
    const m = filmEnvironmentMatrix(stack, { illuminant: 'D93' });
    const tinted = filmXyz(stack, { illuminant: 'D93', lightTint: c });
    const viaM = reflectedXyz(m, c);
    for (let k = 0; k < 3; k++) expect(Math.abs(viaM[k]! - tinted[k]!)).toBeLessThan(ALGEBRAIC_TOL);
  });

  it('of a bare interface (d = 0, glass) under D65 is R₀ times the identity in linear sRGB: every colour reflected as itself, dimmed', () => {
    const r0 = ((1.5 - 1) / (1.5 + 1)) ** 2;
    const m = filmEnvironmentMatrix(film(1.33, 1.5, 0), { illuminant: 'D65' });
    for (let j = 0; j < 3; j++) {
      const column = [m[j]!, m[3 + j]!, m[6 + j]!] as const;
      const rgb = applyMatrix3(XYZ_TO_LINEAR_SRGB, column);
      for (let k = 0; k < 3; k++) expect(Math.abs(rgb[k]! - (k === j ? r0 : 0))).toBeLessThan(r0 * TINTED_WHITE_RGB_TOL);
    }
  });
});

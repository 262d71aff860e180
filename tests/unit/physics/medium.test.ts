/**
 * The media (src/physics/medium.ts, namedMedia.ts): the published tables and formulas against
 * values read from their sources (the refractiveindex.info database's files, at rows and between
 * them), the interpolant's exactness at its nodes, the domain of every named medium over the colour
 * band, and the one parser every entry point shares.
 */
import { describe, expect, it } from 'vitest';
import { COMPLEX_INDEX_DOMAIN, FILM_STACK_DOMAIN } from '../../../src/physics/filmReflectance.ts';
import { JOHNSON_CHRISTY_1972 } from '../../../src/physics/data/johnsonChristy1972.ts';
import { JOHNSON_CHRISTY_1974 } from '../../../src/physics/data/johnsonChristy1974.ts';
import { QUERRY_1985 } from '../../../src/physics/data/querry1985.ts';
import { SARKAR_2019 } from '../../../src/physics/data/sarkar2019.ts';
import {
  type Medium,
  assertMedium,
  indexJson,
  mediumFromJson,
  mediumIndexAt,
  mediumText,
  parseMediumText,
  readMedium,
} from '../../../src/physics/medium.ts';
import { FILM_MATERIALS, MEDIUM_NAMES, type MediumName, namedRangeNm } from '../../../src/physics/namedMedia.ts';
import { type NkTable, tabulatedIndex } from '../../../src/physics/tabulatedIndex.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { FOUR_DIGIT_REL_TOL, TABLE_SUBSAMPLE_TOL } from '../../tolerances.ts';

/** Each tabulated medium and its table. */
const TABLES: [MediumName, NkTable][] = [
  ...(['Au', 'Ag', 'Cu'] as const).map((m): [MediumName, NkTable] => [m, JOHNSON_CHRISTY_1972[m]]),
  ...(['Ti', 'Fe', 'Cr', 'Ni'] as const).map((m): [MediumName, NkTable] => [m, JOHNSON_CHRISTY_1974[m]]),
  ['Fe3O4', QUERRY_1985.Fe3O4],
  ['TiO2', SARKAR_2019.TiO2],
];

const at = (m: Medium, lambdaNm: number) => {
  const v = mediumIndexAt(m, lambdaNm);
  return typeof v === 'number' ? { re: v, im: 0 } : v;
};

describe('named media: the published values', () => {
  it('gold at 548.6 nm (2.26 eV) is 0.43 + 2.455i (Johnson & Christy 1972)', () => {
    expect(at('Au', 548.6)).toEqual({ re: 0.43, im: 2.455 });
  });

  it('the interpolant passes through every row of every table exactly', () => {
    for (const [m, rows] of TABLES)
      for (const [lambdaUm, n, k] of rows)
        expect(at(m, Number((lambdaUm * 1000).toPrecision(12))), `${mediumText(m)} ${lambdaUm}`).toEqual({ re: n, im: k });
  });

  it('values read from the sources, other than the stored rows', () => {
    // [medium, λ nm, n, k, relative tolerance]: the Rakić LD tabulation (4 digits, Al/nk/Rakic-LD.yml),
    // Sarkar's 1 nm table between the 10 nm rows kept (TiO2/nk/Sarkar.yml), Malitson's n_d.
    const points: [Medium, number, number, number, number][] = [
      ['Al', 381.92, 0.41133, 4.4863, FOUR_DIGIT_REL_TOL],
      ['Al', 550.33, 0.96708, 6.4617, FOUR_DIGIT_REL_TOL],
      ['Al', 655.16, 1.4452, 7.5178, FOUR_DIGIT_REL_TOL],
      ['Al', 826.62, 2.6882, 8.1165, FOUR_DIGIT_REL_TOL],
      ['TiO2', 455, 2.241484, 0, TABLE_SUBSAMPLE_TOL],
      ['TiO2', 555, 2.161723, 0, TABLE_SUBSAMPLE_TOL],
      ['TiO2', 655, 2.123687, 0, TABLE_SUBSAMPLE_TOL],
      ['TiO2', 385, 2.381574, 0, TABLE_SUBSAMPLE_TOL],
      ['SiO2', 587.5618, 1.4585, 0, FOUR_DIGIT_REL_TOL],
    ];
    for (const [m, l, n, k, tol] of points) {
      const v = at(m, l);
      expect(Math.abs(v.re - n) / n, `${mediumText(m)} n at ${l}`).toBeLessThan(tol);
      expect(Math.abs(v.im - k) / Math.max(k, 1), `${mediumText(m)} k at ${l}`).toBeLessThan(tol);
    }
  });

  it('every named medium is finite, absorbing or transparent (k ≥ 0) and inside the complex domain at every nm of 380–830', () => {
    const { n, k } = COMPLEX_INDEX_DOMAIN;
    for (const m of MEDIUM_NAMES)
      for (let l = 380; l <= 830; l++) {
        const v = at(m, l);
        expect(v.re >= n.min && v.re <= n.max && v.im >= k.min && v.im <= k.max, `${m} at ${l}: ${JSON.stringify(v)}`).toBe(true);
      }
  });

  it('between rows n and k stay between their neighbours (monotone cubic: no overshoot)', () => {
    for (const [m, rows] of [
      ['Ag', JOHNSON_CHRISTY_1972.Ag],
      ['Fe3O4', QUERRY_1985.Fe3O4],
    ] as const)
      for (let i = 0; i + 1 < rows.length; i++) {
        const [a, b] = [rows[i]!, rows[i + 1]!];
        for (let t = 0.1; t < 1; t += 0.2) {
          const v = at(m, (a[0] + t * (b[0] - a[0])) * 1000);
          expect(v.re).toBeGreaterThanOrEqual(Math.min(a[1], b[1]));
          expect(v.re).toBeLessThanOrEqual(Math.max(a[1], b[1]));
          expect(v.im).toBeGreaterThanOrEqual(Math.min(a[2], b[2]));
          expect(v.im).toBeLessThanOrEqual(Math.max(a[2], b[2]));
        }
      }
  });

  it('every film material is a real index within the film index domain at every nm of 380–830', () => {
    const { min, max } = FILM_STACK_DOMAIN.nFilm;
    for (const m of FILM_MATERIALS)
      for (let l = 380; l <= 830; l++) {
        const v = mediumIndexAt(m, l);
        expect(typeof v === 'number' && v >= min && v <= max, `${m} at ${l}: ${JSON.stringify(v)}`).toBe(true);
      }
  });

  it("the registry's range of a tabulated medium is its table's first to last row", () => {
    for (const [m, rows] of TABLES) expect(namedRangeNm(m), m).toEqual(tabulatedIndex(rows).rangeNm);
  });

  it('each medium covers the colour band with a row beyond each end', () => {
    for (const m of MEDIUM_NAMES) {
      const { min, max } = namedRangeNm(m);
      expect(min, m).toBeLessThan(380);
      expect(max, m).toBeGreaterThan(830);
    }
  });
});

describe('media: the parser every entry point shares', () => {
  it('reads names, complex:n,k, numbers, water and Cauchy films, and writes them back', () => {
    for (const text of ['Au', 'TiO2', 'complex:2.6,3.4', '1.33', 'water', 'cauchy:1.45,6000']) {
      const m = parseMediumText(text);
      expect(m).not.toBeNull();
      expect(mediumText(m!)).toBe(text);
    }
    expect(parseMediumText('complex:2.6,3.4')).toEqual({ complex: [2.6, 3.4] });
    expect(mediumFromJson({ complex: [0.43, 2.455] })).toEqual({ complex: [0.43, 2.455] });
    expect(mediumFromJson('Ni')).toBe('Ni');
    expect(mediumFromJson({ complex: [1, 2], x: 1 })).toBeNull();
    expect(mediumFromJson({ complex: [1] })).toBeNull();
    expect(mediumFromJson({ complex: ['1', 2] })).toBeNull();
    expect(indexJson(1.5)).toBe(1.5);
    expect(indexJson({ re: 2.2, im: 0 })).toBe(2.2);
    expect(indexJson({ re: 0.43, im: 2.455 })).toEqual({ n: 0.43, k: 2.455 });
  });

  it('refuses k < 0, n ≤ 0, unknown names and a complex or named outside, saying why', () => {
    const refused: [string, 'film' | 'inside' | 'outside', RegExp | null][] = [
      ['complex:0.5,-0.1', 'inside', /k is -0\.1, below 0/],
      ['complex:0,1', 'film', /n is 0, below 0\.01/],
      ['complex:-1,1', 'inside', /n is -1, below 0\.01/],
      ['complex:1,1,1', 'film', null],
      ['complex:', 'film', null],
      ['gold', 'inside', null],
      ['au', 'inside', null],
      ['Au', 'outside', /the outside is transparent/],
      ['complex:1.5,0', 'outside', /the outside is transparent/],
      ['0.5', 'film', /below 1/],
    ];
    for (const [text, role, why] of refused) {
      const reading = readMedium(text, role);
      expect('problem' in reading, text).toBe(true);
      const problem = (reading as { problem: string | null }).problem;
      if (why === null) expect(problem, text).toBeNull();
      else expect(problem, text).toMatch(why);
    }
    expect(() => assertMedium('nInside', { complex: [1, -1] }, 'inside')).toThrow(ParameterError);
    expect(() => assertMedium('nInside', { complex: [1, -1] }, 'inside')).toThrow(/^nInside: complex:1,-1 is not allowed \(k is -1/);
    expect(() => assertMedium('nOutside', 'Au', 'outside')).toThrow(/^nOutside: Au is not allowed/);
  });
});

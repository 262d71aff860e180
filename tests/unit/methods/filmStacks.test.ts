/**
 * Every film is a stack of one or more layers; one layer keeps the single film's fast paths bit for
 * bit, and agrees with the transfer-matrix recursion to rounding. The fill registry is the one
 * place that says whether a film is a stack, and which methods draw it.
 */
import { describe, expect, it } from 'vitest';
import { FILM_FILLS, filmFill } from '../../../src/methods/filmFills.ts';
import { filmLayersOf, filmStackOf, singleFilmOf, stackReflectance, stackXyz } from '../../../src/methods/filmStacks.ts';
import { FILM_METHODS, drawnMethod, supports } from '../../../src/methods/methods.ts';
import { layersXyz } from '../../../src/physics/stackColor.ts';
import { dispersiveReflectance, filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { layersReflectance } from '../../../src/physics/transferMatrix.ts';
import { ALGEBRAIC_TOL } from '../../tolerances.ts';

const SOAP = { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 420, angleDeg: 30 } as const;
const WATER_ON_GLASS = { nOutside: 1, nFilm: 'water', nInside: 1.52, thicknessNm: 800, angleDeg: 60 } as const;
const LIGHT = { illuminant: 'D65', polarization: 'unpolarized', normalization: 'white' } as const;

describe('films as stacks (src/methods/filmStacks.ts)', () => {
  it('a film without the layers option is the one layer of nFilm at its thickness', () => {
    expect(filmStackOf(SOAP)).toEqual({ nOutside: 1, films: [{ n: 1.33, thicknessNm: 420 }], nInside: 1, angleDeg: 30 });
    expect(filmStackOf({ ...SOAP, layers: [] })).toEqual(filmStackOf(SOAP));
    expect(filmLayersOf(SOAP)).toEqual([{ n: 1.33, thicknessNm: 'd' }]);
  });

  it("the d layers of the option take the film's thickness, the others keep theirs", () => {
    const layers = [
      { n: 2.1, thicknessNm: 'd' },
      { n: 1.38, thicknessNm: 100 },
    ] as const;
    expect(filmStackOf({ ...SOAP, layers }).films).toEqual([
      { n: 2.1, thicknessNm: 420 },
      { n: 1.38, thicknessNm: 100 },
    ]);
    expect(singleFilmOf(filmStackOf({ ...SOAP, layers }))).toBeNull();
  });

  for (const film of [SOAP, WATER_ON_GLASS])
    it(`one layer (nFilm ${film.nFilm}) takes the single film's path bit for bit, and the recursion's value to rounding`, () => {
      const stack = filmStackOf(film);
      expect(stackXyz(stack, LIGHT)).toEqual(filmXyz(film, LIGHT));
      for (const l of [380, 550, 830]) expect(stackReflectance(l, stack)).toBe(dispersiveReflectance(l, film));
      const recursion = layersXyz(stack, LIGHT);
      stackXyz(stack, LIGHT).forEach((v, k) => expect(Math.abs(v - recursion[k]!)).toBeLessThan(ALGEBRAIC_TOL));
      expect(Math.abs(stackReflectance(550, stack) - layersReflectance(550, stack))).toBeLessThan(ALGEBRAIC_TOL);
    });
});

describe('the fill registry (src/methods/filmFills.ts)', () => {
  const stacked = { ...SOAP, layers: [{ n: 2.1, thicknessNm: 'd' as const }] };

  it('tells a film of constant media, a dispersive film and a stack apart', () => {
    expect(filmFill(SOAP)).toBe('constant');
    expect(filmFill(WATER_ON_GLASS)).toBe('dispersive');
    expect(filmFill({ ...SOAP, nInside: 'Au' })).toBe('dispersive');
    expect(filmFill(stacked)).toBe('stack');
    expect(filmFill({ ...WATER_ON_GLASS, layers: stacked.layers })).toBe('stack');
  });

  it('every method draws a film of constant media; those that do not support a fill give way to the table, which supports every one', () => {
    for (const film of [SOAP, WATER_ON_GLASS, stacked])
      for (const mode of FILM_METHODS) {
        expect(supports(mode, SOAP), mode).toBe(true);
        const drawn = drawnMethod({ ...film, mode });
        if (supports(mode, film)) expect(drawn).toEqual({ mode, instead: null });
        else {
          expect(drawn.mode, mode).toBe('table');
          expect(supports(drawn.mode, film)).toBe(true);
          expect(drawn.instead).toEqual(FILM_FILLS[filmFill(film)].insteadOf!(film, mode));
        }
      }
  });
});

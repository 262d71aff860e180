/** The named-enum contract: a shader's comparison by name picks the same value whatever the list's order. */
import { describe, expect, it } from 'vitest';
import { enumCode, enumConstants, enumDefines } from '../../../src/gpu/enumDefines.ts';

const METHODS = ['exact', 'table', 'fourier', 'three-iridescence'] as const;

describe('enumDefines', () => {
  it('names each value after the define, with dashes as underscores', () => {
    expect(Object.keys(enumConstants('TFC_FILM_MODE', METHODS))).toEqual([
      'TFC_FILM_MODE_EXACT',
      'TFC_FILM_MODE_TABLE',
      'TFC_FILM_MODE_FOURIER',
      'TFC_FILM_MODE_THREE_IRIDESCENCE',
    ]);
  });

  it('the selector equals the chosen value’s constant, for every value and every order of the list', () => {
    const orders = [METHODS, [...METHODS].reverse(), [METHODS[2], METHODS[0], METHODS[3], METHODS[1]]];
    for (const order of orders)
      for (const value of METHODS) {
        const d = enumDefines('TFC_FILM_MODE', order, value);
        const chosen = Object.keys(d).filter((k) => k !== 'TFC_FILM_MODE' && d[k] === d.TFC_FILM_MODE);
        expect(chosen).toEqual([`TFC_FILM_MODE_${value.toUpperCase().replace('-', '_')}`]);
        expect(new Set(Object.values(enumConstants('TFC_FILM_MODE', order))).size).toBe(METHODS.length);
      }
  });

  it('refuses a value that is not in the list, naming the define', () => {
    expect(() => enumCode('TFC_SIDES', ['both', 'front'], 'back' as 'both')).toThrow(/TFC_SIDES.*"back".*both, front/);
  });
});

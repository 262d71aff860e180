/**
 * Every method draws a stack of films: by its own shader where it reads the stack (`stack`), else
 * the table is drawn in its place with a notice, in both catalogues; a single film is drawn as before.
 */
import { describe, expect, it } from 'vitest';
import { EN } from '../../../src/i18n/en.ts';
import { JA } from '../../../src/i18n/ja.ts';
import type { FilmLayer } from '../../../src/physics/stackFilms.ts';
import { FILM_METHODS, drawnMethod, methodReads } from '../../../src/methods/methods.ts';

const STACK: readonly FilmLayer[] = [
  { n: 2.35, thicknessNm: 56.6 },
  { n: 1.46, thicknessNm: 'd' },
];
const FILM = { nFilm: 1.33, nInside: 1 } as const;

describe('methods and stacks of films', () => {
  it('a method that does not read the stack gives way to the table, which does (through its pass)', () => {
    const drawn = FILM_METHODS.map((mode) => [mode, drawnMethod({ ...FILM, layers: STACK, mode })] as const);
    for (const [mode, { mode: shown, instead }] of drawn) {
      if (methodReads(mode, 'stack') || mode === shown) {
        expect(instead, mode).toBeNull();
        continue;
      }
      expect(shown, mode).toBe('table');
      expect(instead?.notice, mode).toBe('app.stackAsTable');
      expect(instead?.values, mode).toEqual({ method: mode, count: '2' });
    }
    // The Fourier method is one of those that give way: it has no closed form for a stack.
    expect(drawnMethod({ ...FILM, layers: STACK, mode: 'fourier' }).mode).toBe('table');
    expect(drawn.filter(([, d]) => methodReads(d.mode, 'table')).length).toBeGreaterThan(1);
  });

  it('a single film (no layers, or none given) is drawn by the method asked for', () => {
    for (const mode of FILM_METHODS) {
      expect(drawnMethod({ ...FILM, layers: [], mode }).mode).toBe(mode);
      expect(drawnMethod({ ...FILM, mode }).mode).toBe(mode);
    }
  });

  it("the notice names the method and the stack's count of films in both catalogues", () => {
    for (const text of [EN['app.stackAsTable'], JA['app.stackAsTable']])
      expect(text).toMatch(/\{method\}.*\{count\}|\{count\}.*\{method\}/s);
  });
});

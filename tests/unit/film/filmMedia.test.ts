/** The film's media: the uniforms TypeScript sets are exactly those the GLSL declares. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MEDIA_KNOT, filmIndexMax, filmMediaUniforms } from '../../../src/film/filmMedia.ts';
import { filmMediaDefines, updateFilmMediaUniforms } from '../../../src/film/filmFillGpu.ts';
import { filmIndexAt } from '../../../src/physics/filmIndex.ts';
import type { Medium } from '../../../src/physics/medium.ts';
import { FEW_OPERATIONS_TOL } from '../../tolerances.ts';

const declared = (file: string): string[] =>
  [...readFileSync(new URL(`../../../shaders/${file}`, import.meta.url), 'utf8').matchAll(/^uniform \w+ (\w+)/gm)].map((m) => m[1]!);

describe('film media uniforms', () => {
  it('filmMedia.ts sets what filmMedia.glsl and medium.glsl declare, no more and no less', () => {
    const glsl = [...declared('film/filmMedia.glsl'), ...declared('physics/medium.glsl')].sort();
    expect(Object.keys(filmMediaUniforms()).sort()).toEqual(glsl);
  });

  it('a tabulated medium takes the knots, an absorbing inside is opaque; constant media (real or complex) take neither the knots nor a wrong opacity', () => {
    const cases: readonly [Medium, Medium, boolean, boolean][] = [
      [1.33, 1, false, false],
      [1.33, 'Au', true, true],
      [1.38, { complex: [0.43, 2.455] }, false, true],
      [1.38, { complex: [1.5, 0] }, false, false],
      ['TiO2', 'SiO2', true, false], // both tabulated; silica is transparent over the band
      ['Fe3O4', 1.5, true, false], // an absorbing film on glass lets light through
      ['water', 1, true, false],
    ];
    for (const [nFilm, nInside, dispersive, opaque] of cases) {
      const d = filmMediaDefines({ nFilm, nInside });
      expect('TFC_DISPERSIVE' in d, JSON.stringify([nFilm, nInside])).toBe(dispersive);
      expect('TFC_OPAQUE_INSIDE' in d, JSON.stringify([nFilm, nInside])).toBe(opaque);
    }
  });

  it('sets ñ as [n, k]: gold’s knot at 550 nm is its Johnson & Christy value there, within the interpolation', () => {
    const u = filmMediaUniforms();
    updateFilmMediaUniforms(u, { nOutside: 1, nFilm: 1.38, nInside: 'Au' });
    expect(u.uNFilm.value).toEqual([1.38, 0]);
    const i = (550 - 380) / 5; // knots every 5 nm from 380 nm
    // A knot's fields by name, as filmMedia.glsl reads them (medium.glsl holds one vec4 per knot).
    expect(MEDIA_KNOT.texels).toBe(1);
    const knot = u.uMediaKnots.value.subarray(i * MEDIA_KNOT.floats, (i + 1) * MEDIA_KNOT.floats);
    const [filmN, filmK] = knot.subarray(MEDIA_KNOT.offsets.FILM);
    const [insideN, insideK] = knot.subarray(MEDIA_KNOT.offsets.INSIDE);
    // Johnson & Christy 1972 list gold at 548.6 nm as 0.43 + 2.455i and at 582.1 nm as 0.29 + 2.863i.
    expect([filmN, filmK]).toEqual([Math.fround(1.38), 0]);
    expect(insideN! < 0.43 && insideN! > 0.29).toBe(true);
    expect(insideK! > 2.455 && insideK! < 2.863).toBe(true);
  });

  it("filmIndexMax: a constant film's n; a normally dispersive film's n at the band's short end", () => {
    expect(filmIndexMax(1.38)).toBe(1.38);
    expect(filmIndexMax({ complex: [2.6, 3.4] })).toBe(2.6);
    expect(filmIndexMax('water')).toBe(filmIndexAt('water', 380));
    expect(Math.abs(filmIndexMax({ cauchy: [1.45, 6000, 0] }) - (1.45 + 6000 / 380 ** 2))).toBeLessThan(FEW_OPERATIONS_TOL);
  });
});

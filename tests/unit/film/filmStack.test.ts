/**
 * A stack of films on the GPU's side (src/film/filmStack.ts): its texture holds, by the record's
 * names, each layer's ñ at every bin's centre as the float64 medium gives it, its thickness or the
 * flag that it follows the field, and the inside last; a stack picks the finer bins, the
 * recursion's defines and no dispersive film's; its table follows the field only where a layer does.
 */
import { describe, expect, it } from 'vitest';
import { FILM_LAYER, filmStackTexels, stackFieldIndex } from '../../../src/film/filmStack.ts';
import { filmMediaDefines, filmSpectralBins, filmStackDefines } from '../../../src/film/filmFillGpu.ts';
import { tableKey } from '../../../src/film/filmTable.ts';
import { FilmTablePass } from '../../../src/film/filmTablePass.ts';
import { asComplex } from '../../../src/physics/complex.ts';
import { type FilmLayer, LAYERS_DOMAIN } from '../../../src/physics/stackFilms.ts';
import { mediumIndexAt } from '../../../src/physics/medium.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM } from '../../../src/physics/spectralWeights.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';

const FIXED: readonly FilmLayer[] = [
  { n: 'TiO2', thicknessNm: 56.6 },
  { n: 1.46, thicknessNm: 91.1 },
];
const FOLLOWING: readonly FilmLayer[] = [
  { n: 1.68, thicknessNm: 'd' },
  { n: 1.43, thicknessNm: 30 },
  { n: 'water', thicknessNm: 'd' },
];

/** A texel's field by the record's offsets (as transferMatrix.glsl reads it). */
const field = (data: Float32Array, texel: number, name: keyof typeof FILM_LAYER.fields): number[] => {
  const at = texel * FILM_LAYER.floats + FILM_LAYER.offsets[name];
  return [...data.subarray(at, at + FILM_LAYER.fields[name])];
};

describe('a stack of films on the GPU', () => {
  it("holds each layer's ñ at the bins' centres, its thickness or the field's flag, and the inside last", () => {
    const bins = 150;
    const layers = [...FIXED, ...FOLLOWING];
    const data = filmStackTexels({ films: layers, nInside: 'Au', bins });
    expect(data.length).toBe(FILM_LAYER.floats * bins * (layers.length + 1));
    const rows = [...layers, { n: 'Au', thicknessNm: 0 } as const];
    for (const [row, layer] of rows.entries())
      for (const b of [0, 77, bins - 1]) {
        const texel = row * bins + b;
        const n = asComplex(mediumIndexAt(layer.n, LAMBDA_MIN_NM + ((b + 0.5) * LAMBDA_SPAN_NM) / bins));
        const [re, im] = field(data, texel, 'N');
        expect(re).toBeCloseTo(Math.fround(n.re), 6);
        expect(im).toBeCloseTo(Math.fround(n.im), 6);
        expect(field(data, texel, 'FOLLOWS_FIELD')).toEqual([layer.thicknessNm === 'd' ? 1 : 0]);
        expect(field(data, texel, 'THICKNESS_NM')).toEqual([layer.thicknessNm === 'd' ? 0 : Math.fround(layer.thicknessNm)]);
      }
  });

  it("takes the finer bins, the recursion's defines up to the most layers, and none of a dispersive film's", () => {
    const q = DEFAULT_FILM_QUALITY;
    const stacked = { nFilm: 'water', nInside: 'water', layers: FIXED } as const;
    expect(filmSpectralBins(stacked, q, q.exactSpectralBins)).toBe(q.dispersiveSpectralBins);
    expect(filmSpectralBins({ nFilm: 1.33, nInside: 1, layers: [] }, q, q.exactSpectralBins)).toBe(q.exactSpectralBins);
    expect(filmStackDefines(stacked)).toMatchObject({ TFC_FILM_LAYERS: 1, TFC_FILM_LAYERS_MAX: LAYERS_DOMAIN.count.max });
    expect(filmStackDefines({ nFilm: 1.33, nInside: 1, layers: [] })).toEqual({});
    expect(filmMediaDefines(stacked)).not.toHaveProperty('TFC_DISPERSIVE');
    expect(filmMediaDefines({ ...stacked, layers: [] })).toHaveProperty('TFC_DISPERSIVE');
  });

  it("resolves the field's fringes by the sum of its following layers' largest indices", () => {
    const water = Math.max(...Array.from({ length: 150 }, (_, b) => asComplex(mediumIndexAt('water', LAMBDA_MIN_NM + 3 * (b + 0.5))).re));
    expect(stackFieldIndex(FOLLOWING, 150)).toBeCloseTo(1.68 + water, 12);
    expect(stackFieldIndex(FIXED, 150)).toBeNull();
  });

  it("builds a stack of fixed layers as two equal columns, whatever the field's range, and one that follows the field over it", () => {
    const pass = new FilmTablePass(DEFAULT_FILM_QUALITY);
    const fixed = { ...DEFAULT_SETTINGS, layers: FIXED };
    expect(pass.fullGrid(fixed, 800).width).toBe(2);
    expect(tableKey(fixed, 1200)).toBe(tableKey(fixed, 800));
    const following = { ...DEFAULT_SETTINGS, layers: FOLLOWING };
    expect(pass.fullGrid(following, 800).width).toBeGreaterThan(pass.fullGrid({ ...DEFAULT_SETTINGS, layers: [] }, 800).width);
    expect(pass.fullGrid(following, 1200).width).toBeGreaterThan(pass.fullGrid(following, 800).width);
    expect(tableKey(following, 1200)).not.toBe(tableKey(following, 800));
    expect(tableKey(following, 800)).not.toBe(tableKey(fixed, 800));
    pass.dispose();
  });
});

/** The film table's width: the thick end's cell, max · power / (width − 1), against the knob and the film's index. */
import { describe, expect, it } from 'vitest';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { CELL_FILM_INDEX, filmTableLookupColumns, filmTableWidth } from '../../../src/settings/filmTableLayout.ts';

const layout = DEFAULT_FILM_QUALITY.table;
const thickEndCellNm = (maxNm: number, width: number) => (maxNm * layout.thicknessPower) / (width - 1);

describe('filmTableWidth', () => {
  it('takes the fewest steps of 64 whose thick-end cell is at most thickEndCellNm, for films up to CELL_FILM_INDEX', () => {
    for (const [maxNm, nFilm] of [
      [2000, CELL_FILM_INDEX],
      [1000, 1.2],
      [700, 1],
    ] as const) {
      const width = filmTableWidth(layout, maxNm, nFilm);
      expect(width % 64).toBe(0);
      expect(thickEndCellNm(maxNm, width)).toBeLessThanOrEqual(layout.thickEndCellNm);
      expect(thickEndCellNm(maxNm, width - 64)).toBeGreaterThan(layout.thickEndCellNm);
    }
    // 2 × 2000 / 8 + 1 = 501 texels wanted.
    expect(filmTableWidth(layout, 2000, 1.33)).toBe(512);
  });

  it('shortens the cell by CELL_FILM_INDEX / n for a film of larger index n: as many cells to a fringe λ/(2n)', () => {
    const n = 2 * CELL_FILM_INDEX;
    const width = filmTableWidth(layout, 1000, n);
    expect(thickEndCellNm(1000, width)).toBeLessThanOrEqual(layout.thickEndCellNm / 2);
    expect(thickEndCellNm(1000, width - 64)).toBeGreaterThan(layout.thickEndCellNm / 2);
    expect(width).toBe(512); // 2 × 1000 / 4 + 1 = 501 wanted
  });

  it('stops at the layout width', () => {
    expect(filmTableWidth(layout, 20000, 1.33)).toBe(layout.width);
    expect(filmTableWidth(layout, 20000, 2.5)).toBe(layout.width);
  });
});

describe('filmTableLookupColumns', () => {
  // Texel k of a table 65 wide over 0..1000 nm holds d = 1000 · (k / 64)^2.
  const columns = (thicknessesNm: number[]) => filmTableLookupColumns(layout, thicknessesNm, 1000, 65);
  const atTexel = (k: number) => 1000 * (k / 64) ** 2;

  it('between two texel centres, those two columns', () => {
    expect(columns([atTexel(10.5)])).toEqual([[10, 12]]);
    expect(columns([atTexel(0.5)])).toEqual([[0, 2]]);
  });

  it('at a texel centre, its neighbours on both sides too (a float32 lookup may land on either side)', () => {
    expect(columns([atTexel(10)])).toEqual([[9, 12]]);
  });

  it('at the ends, and beyond them (clamped as the lookup clamps), only columns inside the table', () => {
    expect(columns([0])).toEqual([[0, 2]]);
    expect(columns([1000])).toEqual([[63, 65]]);
    expect(columns([5000])).toEqual([[63, 65]]);
  });

  it('merges what overlaps or touches, in order', () => {
    expect(columns([atTexel(40.5), atTexel(10.5), atTexel(11.5), atTexel(30.5)])).toEqual([
      [10, 13],
      [30, 32],
      [40, 42],
    ]);
  });
});

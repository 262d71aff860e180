/**
 * The film table's shape: its size, its spectral bins, and where its texels sit
 * (shaders/film/filmTableLayout.glsl holds the mapping; both the table pass and the lookup use it).
 * Texel u along thickness holds d = max · u^thicknessPower; row v of each half holds
 * cos θ_i = v^cosPower. Powers above 1 put texels where colour changes fastest: thin films and
 * grazing incidence (R rises steeply as cos θ_i → 0).
 */
export const TABLE_FILLS = ['binned', 'series'] as const;

export interface FilmTableLayout {
  /** texels along thickness at most */
  readonly width: number;
  /**
   * The thickness cell wanted at the table's thick end: a table over thin films needs fewer
   * texels (`filmTableWidth`), and a smaller table is built sooner.
   */
  readonly thickEndCellNm: number;
  /** rows per half (outside view, inside view) */
  readonly rows: number;
  readonly spectralBins: number;
  readonly thicknessPower: number;
  readonly cosPower: number;
  /** how texels are filled: `binned` (cell-averaged bins) or `series` (the Airy series at the texel) */
  readonly fill: (typeof TABLE_FILLS)[number];
}

/**
 * Texels along thickness for a table up to `maxThicknessNm`: enough that the thick end's cell,
 * max · thicknessPower / (width − 1), is at most `thickEndCellNm`, in steps of 64, at most `width`.
 */
export function filmTableWidth(l: FilmTableLayout, maxThicknessNm: number): number {
  const wanted = (maxThicknessNm * l.thicknessPower) / l.thickEndCellNm + 1;
  return Math.min(l.width, 64 * Math.max(1, Math.ceil(wanted / 64)));
}

/** cos θ_i of the table's row `row` of `l.rows` (twin of filmTableCosIncidence in the GLSL). */
export const filmTableCosIncidence = (l: FilmTableLayout, row: number): number => (row / (l.rows - 1)) ** l.cosPower;

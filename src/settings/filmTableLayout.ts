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
   * The thickness cell wanted at the table's thick end for a film of index up to
   * `CELL_FILM_INDEX`: a table over thin films needs fewer texels (`filmTableWidth`), and a smaller
   * table is built sooner.
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
 * The film index `thickEndCellNm` is given for (a soap film's). A film's fringes are λ/(2 n_b cos θ_r)
 * apart in thickness, so a film of larger index n_b gets cells CELL_FILM_INDEX / n_b as long: as
 * many to a fringe (Fe3O4, n_b up to 2.46: 4.3 nm cells for 8).
 */
export const CELL_FILM_INDEX = 1.33;

/**
 * Texels along thickness for a table up to `maxThicknessNm` of a film whose real index reaches
 * `filmIndex` in the band: enough that the thick end's cell, max · thicknessPower / (width − 1), is
 * at most `thickEndCellNm` (times CELL_FILM_INDEX / filmIndex above that index), in steps of 64, at
 * most `width`.
 */
export function filmTableWidth(l: FilmTableLayout, maxThicknessNm: number, filmIndex: number): number {
  const cellNm = l.thickEndCellNm * Math.min(1, CELL_FILM_INDEX / filmIndex);
  const wanted = (maxThicknessNm * l.thicknessPower) / cellNm + 1;
  return Math.min(l.width, 64 * Math.max(1, Math.ceil(wanted / 64)));
}

/** cos θ_i of the table's row `row` of `l.rows` (twin of filmTableCosIncidence in the GLSL). */
export const filmTableCosIncidence = (l: FilmTableLayout, row: number): number => (row / (l.rows - 1)) ** l.cosPower;

/** How far from a texel centre, in texels, a GPU's float32 lookup may land: more than its rounding, far less than a texel. */
const LOOKUP_MARGIN_TEXELS = 0.01;

/**
 * The column ranges [from, to), merged and in order, that looking up a table `width` texels wide
 * over 0..maxThicknessNm at these thicknesses reads: a lookup at u · (width − 1) (u as
 * tfcFilmTableUv in shaders/film/filmTableLayout.glsl gives it) blends the two columns around it, taken within
 * LOOKUP_MARGIN_TEXELS so that rounding on the GPU cannot reach a column left out.
 */
export function filmTableLookupColumns(
  l: Pick<FilmTableLayout, 'thicknessPower'>,
  thicknessesNm: readonly number[],
  maxThicknessNm: number,
  width: number,
): [number, number][] {
  const needed = new Set<number>();
  for (const d of thicknessesNm) {
    const x = Math.min(1, Math.max(0, d / maxThicknessNm)) ** (1 / l.thicknessPower) * (width - 1);
    const from = Math.max(0, Math.floor(x - LOOKUP_MARGIN_TEXELS));
    const to = Math.min(width - 1, Math.ceil(x + LOOKUP_MARGIN_TEXELS));
    for (let c = from; c <= to; c++) needed.add(c);
  }
  const ranges: [number, number][] = [];
  for (const c of [...needed].sort((a, b) => a - b)) {
    const last = ranges.at(-1);
    if (last && last[1] === c) last[1] = c + 1;
    else ranges.push([c, c + 1]);
  }
  return ranges;
}

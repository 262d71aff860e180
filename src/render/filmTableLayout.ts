/**
 * The film table's shape: its size, its spectral bins, and where its texels sit
 * (shaders/filmTableLayout.glsl holds the mapping; both the table pass and the lookup use it).
 * Texel u along thickness holds d = max · u^thicknessPower; row v of each half holds
 * cos θ_i = v^cosPower. Powers above 1 put texels where colour changes fastest: thin films and
 * grazing incidence (R rises steeply as cos θ_i → 0).
 */
export interface FilmTableLayout {
  /** texels along thickness */
  readonly width: number;
  /** rows per half (outside view, inside view) */
  readonly rows: number;
  readonly spectralBins: number;
  readonly thicknessPower: number;
  readonly cosPower: number;
  /** how texels are filled: `binned` (cell-averaged bins) or `series` (the Airy series at the texel) */
  readonly fill: 'binned' | 'series';
}

/** The defines shaders/filmTableLayout.glsl reads. */
export const filmTableLayoutDefines = (l: FilmTableLayout): Record<string, number> => ({
  FILM_TABLE_WIDTH: l.width,
  FILM_TABLE_ROWS: l.rows,
  FILM_TABLE_THICKNESS_POWER: l.thicknessPower,
  FILM_TABLE_COS_POWER: l.cosPower,
  TABLE_FILL: l.fill === 'series' ? 1 : 0,
});

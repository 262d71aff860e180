import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { packTexelRecord, texelRecord } from '../gpu/texelRecord.ts';
import { airySeriesTerms } from '../physics/airySeries.ts';
import { filmOptics } from '../physics/filmReflectance.ts';
import { absorbsInBand, mediumStackAt, transparentIndexAt } from '../physics/medium.ts';
import { SODIUM_D_NM } from './filmMedia.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { type FilmTableLayout, filmTableCosIncidence } from '../settings/filmTableLayout.ts';

/**
 * A row's record, read by these names in shaders/film/filmTable.glsl (`tfcRowSeries`): the series'
 * C₀, B, q of channel 0 and of channel 1, the path per nm of thickness (2 n_b cos θ_r) and 1 where
 * it is real (0: an evanescent film, no series).
 */
export const AIRY_ROW = texelRecord('TFC_AIRY_ROW', {
  C0_0: 1,
  B_0: 2,
  Q_0: 2,
  C0_1: 1,
  B_1: 2,
  Q_1: 2,
  PATH_PER_NM: 1,
  REAL_PATH: 1,
});

/**
 * The Airy series' C₀, B, q of every row of the film table (they depend on cos θ_i and the
 * indices, not on the thickness), computed in float64 by src/physics for the table pass
 * (shaders/film/filmTable.glsl, `tfcRowSeries`): an AIRY_ROW record per row, the outside half's
 * rows first, then the inside half's (media swapped; none for an opaque inside, whose half the
 * pass leaves black).
 * ~1 ms for 256 rows, instead of the Fresnel terms per texel. The media are constant (real or
 * complex: an absorbing film's complex path is marked as having no series).
 */
export function airySeriesRows(
  s: Pick<FilmSettings, 'nOutside' | 'nFilm' | 'nInside' | 'polarization'>,
  layout: FilmTableLayout,
  data: Float32Array,
): void {
  const halves = absorbsInBand(s.nInside) ? 1 : 2;
  for (let half = 0; half < halves; half++) {
    // From inside the light comes from the (transparent) inside: its n.
    const [nOutside, nInside] = half === 0 ? [s.nOutside, s.nInside] : [transparentIndexAt(s.nInside, SODIUM_D_NM), s.nOutside];
    for (let row = 0; row < layout.rows; row++) {
      const cos = filmTableCosIncidence(layout, row);
      const angleDeg = (Math.acos(Math.min(1, cos)) * 180) / Math.PI;
      // Thickness 1 nm: any d > 0 has the same terms, and the path per nm is then Δ itself.
      const optics = filmOptics(
        mediumStackAt({ nOutside, nFilm: s.nFilm, nInside, thicknessNm: 1, angleDeg }, SODIUM_D_NM),
        s.polarization,
      );
      const [t0, t1 = t0] = optics.channels.map(airySeriesTerms);
      const path = optics.opticalPathNm;
      packTexelRecord(AIRY_ROW, data, half * layout.rows + row, {
        C0_0: t0!.c0,
        B_0: [t0!.b.re, t0!.b.im],
        Q_0: [t0!.q.re, t0!.q.im],
        C0_1: t1!.c0,
        B_1: [t1!.b.re, t1!.b.im],
        Q_1: [t1!.q.re, t1!.q.im],
        PATH_PER_NM: path.re,
        REAL_PATH: path.im === 0 ? 1 : 0,
      });
    }
  }
}

/** A texture for airySeriesRows of a layout (filled and uploaded by FilmTablePass). */
export function airySeriesRowsTexture(layout: FilmTableLayout): DataTexture {
  const texture = new DataTexture(
    new Float32Array(AIRY_ROW.floats * 2 * layout.rows),
    AIRY_ROW.texels,
    2 * layout.rows,
    RGBAFormat,
    FloatType,
  );
  texture.minFilter = texture.magFilter = NearestFilter;
  return texture;
}

import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { packTexelRecord, texelRecord } from '../gpu/texelRecord.ts';
import { pathPerNmAt } from '../physics/binnedIntegration.ts';
import type { FilmStack } from '../physics/filmReflectance.ts';
import type { Complex } from '../physics/complex.ts';
import { type Polarization, filmOptics } from '../physics/filmReflectance.ts';
import { type Medium, absorbsInBand, mediumStackAt, transparentIndexAt } from '../physics/medium.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM } from '../physics/spectralWeights.ts';
import { type FilmTableLayout, filmTableCosIncidence } from '../settings/filmTableLayout.ts';

/**
 * The record of a row and bin, read by these names in shaders/physics/binnedIntegration.glsl
 * (`tfcDispersiveBin`): the Fresnel terms of eq (13) of channels 0 and 1 (complex), the optical
 * path per nm of thickness at the bin's centre (complex) and at its two ends (real part).
 */
export const DISPERSIVE_BIN = texelRecord('TFC_DISPERSIVE_BIN', {
  RAB_0: 2,
  MULTIPLE_0: 2,
  ROUND_TRIP_0: 2,
  RAB_1: 2,
  MULTIPLE_1: 2,
  ROUND_TRIP_1: 2,
  PATH_PER_NM: 2,
  PATH_PER_NM_LOW: 1,
  PATH_PER_NM_HIGH: 1,
});

const reIm = (z: Complex): readonly [number, number] => [z.re, z.im];

export interface DispersiveFilm {
  readonly nOutside: number;
  readonly nFilm: Medium;
  readonly nInside: Medium;
  readonly polarization: Polarization;
}

/**
 * What the table pass of a film whose media depend on λ needs per row (cos θ_i, medium) and spectral
 * bin, none of it depending on the thickness: the Fresnel terms of eq (13) at ñ_b, ñ_c of the bin's
 * centre (both channels), and the optical path per nm of thickness, 2 ñ_b(λ) cos θ_r(λ), at the bin's
 * centre (complex) and its two ends (real part) — computed in float64 by src/physics for
 * the table pass (shaders/film/filmTable.glsl, through binnedIntegration.glsl's `tfcDispersiveBin`),
 * instead of the Fresnel terms per texel and bin.
 * A DISPERSIVE_BIN record per (row, bin), the bins of a row together; the outside half's rows first,
 * then the inside half's (none for an opaque inside, whose half the pass leaves black).
 */
export function dispersiveRows(s: DispersiveFilm, layout: FilmTableLayout, data: Float32Array): void {
  const bins = layout.spectralBins;
  const width = LAMBDA_SPAN_NM / bins;
  const halves = absorbsInBand(s.nInside) ? 1 : 2;
  for (let half = 0; half < halves; half++) {
    const [nOutside, nInside]: [Medium, Medium] = half === 0 ? [s.nOutside, s.nInside] : [s.nInside, s.nOutside];
    for (let row = 0; row < layout.rows; row++) {
      const cos = filmTableCosIncidence(layout, row);
      const angleDeg = (Math.acos(Math.min(1, cos)) * 180) / Math.PI;
      const stack: Omit<FilmStack<Medium>, 'thicknessNm'> = { nOutside, nFilm: s.nFilm, nInside, angleDeg };
      for (let b = 0; b < bins; b++) {
        const l1 = LAMBDA_MIN_NM + b * width;
        const center = l1 + width / 2;
        // Thickness 1 nm: any d > 0 has the same terms, and the path per nm is then Δ itself.
        const at = { ...stack, nOutside: transparentIndexAt(nOutside, center), thicknessNm: 1 };
        const optics = filmOptics(mediumStackAt(at, center), s.polarization);
        const [c0, c1 = c0] = optics.channels;
        packTexelRecord(DISPERSIVE_BIN, data, (half * layout.rows + row) * bins + b, {
          RAB_0: reIm(c0!.rab),
          MULTIPLE_0: reIm(c0!.multiple),
          ROUND_TRIP_0: reIm(c0!.roundTrip),
          RAB_1: reIm(c1!.rab),
          MULTIPLE_1: reIm(c1!.multiple),
          ROUND_TRIP_1: reIm(c1!.roundTrip),
          PATH_PER_NM: reIm(optics.opticalPathNm),
          PATH_PER_NM_LOW: pathPerNmAt(stack, l1),
          PATH_PER_NM_HIGH: pathPerNmAt(stack, l1 + width),
        });
      }
    }
  }
}

/** The floats dispersiveRows writes for a layout. */
export const dispersiveRowsLength = (layout: FilmTableLayout): number => DISPERSIVE_BIN.floats * layout.spectralBins * 2 * layout.rows;

/** What a dispersive film's row terms follow from: the film and the table's layout (its rows and bins). */
export const dispersiveRowsKey = (film: DispersiveFilm, layout: FilmTableLayout): string =>
  JSON.stringify([{ nOutside: film.nOutside, nFilm: film.nFilm, nInside: film.nInside, polarization: film.polarization }, layout]);

/** dispersiveRows for a key of dispersiveRowsKey, in a new array (on the main thread or in dispersiveRowsWorker.ts). */
export function dispersiveRowsOfKey(key: string): Float32Array {
  const [film, layout] = JSON.parse(key) as [DispersiveFilm, FilmTableLayout];
  const data = new Float32Array(dispersiveRowsLength(layout));
  dispersiveRows(film, layout, data);
  return data;
}

/** A texture for dispersiveRows of a layout (filled and uploaded by FilmTablePass). */
export function dispersiveRowsTexture(layout: FilmTableLayout): DataTexture {
  const texture = new DataTexture(
    new Float32Array(dispersiveRowsLength(layout)),
    DISPERSIVE_BIN.texels * layout.spectralBins,
    2 * layout.rows,
    RGBAFormat,
    FloatType,
  );
  texture.minFilter = texture.magFilter = NearestFilter;
  return texture;
}

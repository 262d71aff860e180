import type { Rgb } from '../physics/colorConversions.ts';
import { illuminantKey } from '../physics/illuminants.ts';
import { type IndexJson } from '../physics/medium.ts';
import type { ColorCase } from './colorCase.ts';
import type { CaseColor } from './computeCaseColor.ts';

/** One row of a thickness or angle table: the case's colour with its film and a hex code. */
export interface TableRow extends CaseColor {
  readonly thicknessNm: number;
  readonly angleDeg: number;
  /** `#rrggbb` of `srgb8`. */
  readonly hex: string;
}

export const hexColor = (rgb8: Rgb): string => `#${rgb8.map((v) => v.toString(16).padStart(2, '0')).join('')}`;

export function tableRow(c: ColorCase, color: CaseColor): TableRow {
  const { id, ...rest } = color;
  return { id, thicknessNm: c.stack.thicknessNm, angleDeg: c.stack.angleDeg, hex: hexColor(color.srgb8), ...rest };
}

/** A JSON array with one element per line: valid JSON that is still readable and diffable. */
export const jsonLines = (rows: readonly object[]): string =>
  rows.length === 0 ? '[]\n' : `[\n${rows.map((row) => JSON.stringify(row)).join(',\n')}\n]\n`;

const channels = (name: string) => [`${name}R`, `${name}G`, `${name}B`];

/** n and k of an index as JSON reports it (k = 0 for a real one). */
const nk = (index: IndexJson): [number, number] => (typeof index === 'number' ? [index, 0] : [index.n, index.k]);

/**
 * A table as CSV: a header line, then one line per row; R(λ) columns are named `R_<λ>nm`, the film's
 * ñ_b(λ) = n + ik columns `nFilm_<λ>nm` and `kFilm_<λ>nm` (with `layerCount` films, film i's from
 * the outside, counted from 1, `nLayer<i>_<λ>nm` and `kLayer<i>_<λ>nm`), the inside's `nInside_<λ>nm` and `kInside_<λ>nm`.
 */
export function tableCsv(rows: readonly TableRow[], wavelengthsNm: readonly number[], layerCount = 0): string {
  const films = layerCount === 0 ? ['Film'] : Array.from({ length: layerCount }, (_, i) => `Layer${i + 1}`);
  /** The indices of film f (an entry of `films`) at every wavelength. */
  const filmIndices = (r: TableRow, f: number): readonly IndexJson[] =>
    layerCount === 0 ? (r.nFilm ?? []) : (r.nLayers ?? []).map((atLambda) => atLambda[f]!);
  const header = [
    'id',
    'thicknessNm',
    'angleDeg',
    'hex',
    'illuminant',
    ...channels('lightTint'),
    'normalization',
    'X',
    'Y',
    'Z',
    ...channels('linearSrgb'),
    ...channels('srgb8'),
    ...channels('linearWideGamut'),
    ...channels('displayP3_8'),
    ...wavelengthsNm.map((l) => `R_${l}nm`),
    ...films.flatMap((film) => [...wavelengthsNm.map((l) => `n${film}_${l}nm`), ...wavelengthsNm.map((l) => `k${film}_${l}nm`)]),
    ...wavelengthsNm.map((l) => `nInside_${l}nm`),
    ...wavelengthsNm.map((l) => `kInside_${l}nm`),
  ];
  const line = (r: TableRow) =>
    [
      r.id,
      r.thicknessNm,
      r.angleDeg,
      r.hex,
      illuminantKey(r.illuminant),
      ...r.lightTint,
      r.normalization,
      ...r.xyz,
      ...r.linearSrgb,
      ...r.srgb8,
      ...r.linearWideGamut,
      ...r.displayP3_8,
      ...r.reflectance,
      ...films.flatMap((_, f) => [...filmIndices(r, f).map((i) => nk(i)[0]), ...filmIndices(r, f).map((i) => nk(i)[1])]),
      ...r.nInside.map((i) => nk(i)[0]),
      ...r.nInside.map((i) => nk(i)[1]),
    ].join(',');
  return `${[header.join(','), ...rows.map(line)].join('\n')}\n`;
}

import { type Matrix3, type Rgb, applyMatrix3, encode8, mapToGamut } from '../physics/colorConversions.ts';
import { followsField } from '../physics/stackFilms.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import type { LightTint } from '../physics/lightTint.ts';
import { type Normalization, type Xyz } from '../physics/spectralWeights.ts';
import { type FilmOption, filmLayersOf, filmStackOf, stackXyz } from '../methods/filmStacks.ts';

/** One film colour of the scale. */
export interface ScaleColor {
  readonly thicknessNm: number;
  readonly xyz: Xyz;
  /** 8-bit encoded display RGB (gamut-clipped), for drawing. */
  readonly rgb8: Rgb;
}

export interface ScaleOptions {
  readonly illuminant: IlluminantSpec;
  /** The light's tint (none: untinted). */
  readonly lightTint?: LightTint;
  readonly polarization: Polarization;
  readonly normalization: Normalization;
  /** XYZ → the display's linear RGB (eq 19 for sRGB). */
  readonly xyzToLinearRgb: Matrix3;
}

/**
 * The interference colour scale: the reference colour (eqs 15–18) of the film at one angle for
 * `count` thicknesses from 0 to `maxThicknessNm` — the strip under the plots and the path in
 * the chromaticity diagram. For a stack the thickness is the field's: its FIELD_THICKNESS films
 * take it (a stack with none is the same colour all along).
 */
export function interferenceScale(
  film: Omit<FilmOption, 'thicknessNm'>,
  maxThicknessNm: number,
  count: number,
  o: ScaleOptions,
): ScaleColor[] {
  const colors: ScaleColor[] = [];
  const at = (thicknessNm: number) => stackXyz(filmStackOf({ ...film, thicknessNm }), o);
  // A stack may have no layer that takes the field's thickness: the same colour all along.
  const fixed = followsField(filmLayersOf(film)) ? null : at(0);
  for (let i = 0; i < count; i++) {
    const thicknessNm = (maxThicknessNm * i) / (count - 1);
    const xyz = fixed ?? at(thicknessNm);
    const rgb = mapToGamut(applyMatrix3(o.xyzToLinearRgb, xyz), xyz[1]);
    colors.push({ thicknessNm, xyz, rgb8: [encode8(rgb[0]), encode8(rgb[1]), encode8(rgb[2])] });
  }
  return colors;
}

/** A scale's arguments as one object (what the scale's worker is sent). */
export interface ScaleRequest {
  readonly stack: Omit<FilmOption, 'thicknessNm'>;
  readonly maxThicknessNm: number;
  readonly count: number;
  readonly options: ScaleOptions;
}

export const interferenceScaleOf = (r: ScaleRequest): ScaleColor[] => interferenceScale(r.stack, r.maxThicknessNm, r.count, r.options);

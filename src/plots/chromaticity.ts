import { type Matrix3, type Rgb, applyMatrix3, invert3, xyzToXy } from '../physics/colorConversions.ts';
import { CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, CIE1931_XBAR, CIE1931_YBAR, CIE1931_ZBAR } from '../physics/data/cie1931Cmf2deg.ts';

export type Xy = readonly [number, number];

/**
 * The spectral locus of the CIE 1931 2° observer: the xy chromaticity of each monochromatic
 * light from `fromNm` to `toNm` (the CMF table's 1 nm knots). Beyond ~700 nm the points pile up
 * at the red end, so the plot's default stops there.
 */
export function spectralLocus(fromNm = 380, toNm = 700, stepNm = 1): Xy[] {
  const points: Xy[] = [];
  for (let l = fromNm; l <= toNm; l += stepNm) {
    const i = Math.round((l - CIE1931_CMF_START_NM) / CIE1931_CMF_STEP_NM);
    points.push(xyzToXy([CIE1931_XBAR[i]!, CIE1931_YBAR[i]!, CIE1931_ZBAR[i]!]));
  }
  return points;
}

/**
 * The xy of an RGB space's primaries, from its XYZ → linear RGB matrix (eq 19, eq 20, …): the
 * primaries are the columns of the inverse matrix (the XYZ of R = 1, G = 1, B = 1 alone).
 */
export function gamutTriangle(xyzToLinearRgb: Matrix3): [Xy, Xy, Xy] {
  const toXyz = invert3(xyzToLinearRgb);
  const primary = (rgb: Rgb) => xyzToXy(applyMatrix3(toXyz, rgb));
  return [primary([1, 0, 0]), primary([0, 1, 0]), primary([0, 0, 1])];
}

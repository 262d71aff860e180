import type { Xyz } from './spectralWeights.ts';

/** A 3×3 matrix, row-major. */
export type Matrix3 = readonly [number, number, number, number, number, number, number, number, number];
export type Rgb = readonly [number, number, number];

export const applyMatrix3 = (m: Matrix3, [a, b, c]: readonly [number, number, number]): Rgb => [
  m[0] * a + m[1] * b + m[2] * c,
  m[3] * a + m[4] * b + m[5] * c,
  m[6] * a + m[7] * b + m[8] * c,
];

/** XYZ → linear sRGB, the paper's eq (19) (IEC 61966-2-1's matrix to four decimals). */
export const XYZ_TO_LINEAR_SRGB: Matrix3 = [3.2406, -1.5372, -0.4989, -0.9686, 1.8758, 0.0415, 0.0557, -0.204, 1.057];

/**
 * XYZ → linear "Wide Gamut" RGB, the paper's eq (20): Adobe Wide Gamut RGB, whose white is D50;
 * the paper applies it without chromatic adaptation and so do we.
 */
export const XYZ_TO_LINEAR_WIDE_GAMUT: Matrix3 = [1.4625, -0.1845, -0.2734, -0.5228, 1.4479, 0.0681, 0.0346, -0.0958, 1.2875];

type Xy = readonly [number, number];

/**
 * The RGB → XYZ matrix of an additive colour space, derived from the chromaticities of its
 * primaries and white (SMPTE RP 177): columns are the primaries' XYZ (Y = 1) scaled so
 * that R = G = B = 1 gives the white with Y = 1.
 */
export function rgbToXyzMatrix(red: Xy, green: Xy, blue: Xy, white: Xy): Matrix3 {
  const col = ([x, y]: Xy): Rgb => [x / y, 1, (1 - x - y) / y];
  const [r, g, b] = [col(red), col(green), col(blue)];
  const p: Matrix3 = [r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]];
  const [sr, sg, sb] = applyMatrix3(invert3(p), col(white));
  return [p[0] * sr, p[1] * sg, p[2] * sb, p[3] * sr, p[4] * sg, p[5] * sb, p[6] * sr, p[7] * sg, p[8] * sb];
}

export function invert3(m: Matrix3): Matrix3 {
  const [a, b, c, d, e, f, g, h, i] = m;
  const A = e * i - f * h,
    B = f * g - d * i,
    C = d * h - e * g;
  const det = a * A + b * B + c * C;
  return [
    A / det,
    (c * h - b * i) / det,
    (b * f - c * e) / det,
    B / det,
    (a * i - c * g) / det,
    (c * d - a * f) / det,
    C / det,
    (b * g - a * h) / det,
    (a * e - b * d) / det,
  ];
}

/** D65's chromaticity as colour spaces define it (IEC 61966-2-1, SMPTE EG 432-1). */
export const D65_XY: Xy = [0.3127, 0.329];

/** XYZ → linear Display P3 (SMPTE EG 432-1 primaries, D65 white), derived from its definition. */
export const XYZ_TO_LINEAR_DISPLAY_P3: Matrix3 = invert3(rgbToXyzMatrix([0.68, 0.32], [0.265, 0.69], [0.15, 0.06], D65_XY));

/** The sRGB transfer function (IEC 61966-2-1), linear [0, 1] → encoded [0, 1]; Display P3 uses it too. */
export const srgbEncode = (v: number): number => (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055);

/** Its inverse, encoded → linear. */
export const srgbDecode = (v: number): number => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);

/**
 * What to do with a colour outside the display's gamut (a channel < 0 or > 1):
 * - `clip`: clamp each channel to [0, 1] (default; shifts hue for saturated colours);
 * - `preserve-hue`: move the colour toward the grey of the same luminance until no channel is
 *   negative (a straight line in chromaticity, so the dominant wavelength is kept), then scale
 *   it down until no channel exceeds 1 (which keeps the chromaticity).
 */
export const GAMUT_MAPPINGS = ['clip', 'preserve-hue'] as const;
export type GamutMapping = (typeof GAMUT_MAPPINGS)[number];

/** `luminance` is the colour's Y (with the matrices above, Y = the RGB's luminance). */
export function mapToGamut(rgb: Rgb, luminance: number, mapping: GamutMapping = 'clip'): Rgb {
  const clamp01 = (v: number) => Math.min(1, Math.max(0, v));
  if (mapping === 'clip') return [clamp01(rgb[0]), clamp01(rgb[1]), clamp01(rgb[2])];
  const grey = clamp01(luminance);
  const lowest = Math.min(...rgb);
  const t = lowest < 0 ? grey / (grey - lowest) : 1;
  const mixed = rgb.map((v) => grey + (v - grey) * t);
  const highest = Math.max(...mixed, 1);
  return [clamp01((mixed[0] as number) / highest), clamp01((mixed[1] as number) / highest), clamp01((mixed[2] as number) / highest)];
}

/** 8-bit code of a linear channel: round(255 · sRGB-encode(v)), v already in [0, 1]. */
export const encode8 = (linear: number): number => Math.round(255 * srgbEncode(linear));

/** XYZ → xy chromaticity (for plots and tests). */
export function xyzToXy([X, Y, Z]: Xyz): Xy {
  const s = X + Y + Z;
  return s > 0 ? [X / s, Y / s] : [0, 0];
}

import { type Matrix3, type Rgb, applyMatrix3 } from '../physics/colorConversions.ts';
import type { ToneMapping } from '../settings/filmSettings.ts';

/**
 * The CPU twins of three.js's tone mapping curves (its tonemapping_pars_fragment chunk, which the
 * GPU runs), linear sRGB in and out, for the still image drawn without WebGL2. Matrices are written
 * row by row (three writes them as GLSL columns).
 */

const SRGB_TO_REC2020: Matrix3 = [0.6274, 0.3293, 0.0433, 0.0691, 0.9195, 0.0113, 0.0164, 0.088, 0.8956];
const REC2020_TO_SRGB: Matrix3 = [1.6605, -0.5876, -0.0728, -0.1246, 1.1329, -0.0083, -0.0182, -0.1006, 1.1187];
const AGX_INSET: Matrix3 = [
  0.856627153315983, 0.0951212405381588, 0.0482516061458583, 0.137318972929847, 0.761241990602591, 0.101439036467562, 0.11189821299995,
  0.0767994186031903, 0.811302368396859,
];
const AGX_OUTSET: Matrix3 = [
  1.1271005818144368, -0.11060664309660323, -0.016493938717834573, -0.1413297634984383, 1.157823702216272, -0.016493938717834257,
  -0.14132976349843826, -0.11060664309660294, 1.2519364065950405,
];
/** log2 of 0.18 · 2^−10 and 0.18 · 2^6.5: the log encoding's ends around middle grey. */
const AGX_MIN_EV = -12.47393;
const AGX_MAX_EV = 4.026069;

const clamp01 = (v: number) => Math.min(1, Math.max(0, v));
const map3 = (c: Rgb, f: (v: number) => number): Rgb => [f(c[0]), f(c[1]), f(c[2])];

/** AgX's sigmoid: a sixth-order polynomial fit of its contrast curve on [0, 1]. */
const agxContrast = (x: number) => {
  const x2 = x * x,
    x4 = x2 * x2;
  return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
};

/** AgX (Filament's, after Blender's): log-encode in an inset Rec. 2020, sigmoid, outset, linearise, clip. */
function agx(color: Rgb): Rgb {
  const inset = applyMatrix3(AGX_INSET, applyMatrix3(SRGB_TO_REC2020, color));
  const encoded = map3(inset, (v) => agxContrast(clamp01((Math.log2(Math.max(v, 1e-10)) - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV))));
  const linear = map3(applyMatrix3(AGX_OUTSET, encoded), (v) => Math.max(0, v) ** 2.2);
  return map3(applyMatrix3(REC2020_TO_SRGB, linear), clamp01);
}

/** Khronos PBR Neutral: identity (less a small toe offset) below 0.76, then the peak compressed towards 1 and desaturated. */
function neutral(color: Rgb): Rgb {
  const START = 0.8 - 0.04;
  const DESATURATION = 0.15;
  const x = Math.min(...color);
  const offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  const c = map3(color, (v) => v - offset);
  const peak = Math.max(...c);
  if (peak < START) return c;
  const d = 1 - START;
  const newPeak = 1 - (d * d) / (peak + d - START);
  const g = 1 - 1 / (DESATURATION * (peak - newPeak) + 1);
  return map3(c, (v) => (v * newPeak) / peak + (newPeak - (v * newPeak) / peak) * g);
}

/** A linear sRGB radiance as the display gets it: `none` leaves it (the caller clips), else the curve. */
export function toneMap(color: Rgb, mapping: ToneMapping): Rgb {
  return mapping === 'none' ? color : mapping === 'agx' ? agx(color) : neutral(color);
}

import { type Complex } from './complex.ts';
import { type Matrix3, XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from './colorConversions.ts';
import { type SampledIndex } from './sampledIndex.ts';
import { LAMBDA_MIN_NM, spectralWeights } from './spectralWeights.ts';

/**
 * A metal's complex index from two colours an artist sets, O. Gulbrandsen, "Artist Friendly
 * Metallic Fresnel", JCGT 3(4), 64–72 (2014): the reflectivity r (the normal-incidence
 * reflectance, F0) and the edge tint g (how the colour runs towards grazing), each in [0, 1] per
 * channel. Gulbrandsen's remapping (his eqs for n(r, g) and k(r, n)):
 *   n_min = (1 − r)/(1 + r),  n_max = (1 + √r)/(1 − √r),  n = g·n_min + (1 − g)·n_max,
 *   k = √( (r(n + 1)² − (n − 1)²) / (1 − r) ),
 * so that |(ñ − 1)/(ñ + 1)|² = r exactly for every g: g = 1 takes the smallest n, g = 0 a dielectric (k = 0, n the index whose F0 is r). docs/material.md#a-metal-from-its-colour.
 */

/** r at most this: r → 1 makes k infinite; 0.98 keeps n_min ≥ 0.0101, inside COMPLEX_INDEX_DOMAIN's n ≥ 0.01. */
export const ARTIST_METAL_MAX_REFLECTIVITY = 0.98;

/** ñ = n + ik for one channel, r in [0, 1] (clamped to ARTIST_METAL_MAX_REFLECTIVITY), g in [0, 1]. */
export function artistMetalIndex(reflectivity: number, edgeTint: number): Complex {
  const r = Math.min(ARTIST_METAL_MAX_REFLECTIVITY, Math.max(0, reflectivity));
  const g = Math.min(1, Math.max(0, edgeTint));
  const s = Math.sqrt(r);
  const n = (g * (1 - r)) / (1 + r) + ((1 - g) * (1 + s)) / (1 - s);
  // r(n+1)² − (n−1)² ≥ 0 between n_min and n_max (it vanishes at n_max); max() keeps rounding from a negative root.
  const k = Math.sqrt(Math.max(0, (r * (n + 1) ** 2 - (n - 1) ** 2) / (1 - r)));
  return { re: n, im: k };
}

/**
 * Where each channel's index is placed in λ: the dominant wavelengths (nm) of the sRGB (ITU-R
 * BT.709) primaries against D65, the wavelength on the spectrum locus each primary's hue points to.
 */
export const CHANNEL_WAVELENGTHS_NM = { r: 611.3, g: 549.1, b: 464.3 } as const;

/** Linear RGB, each in [0, 1]. */
export type LinearRgb = readonly [r: number, g: number, b: number];

const CHANNEL_NM = [CHANNEL_WAVELENGTHS_NM.b, CHANNEL_WAVELENGTHS_NM.g, CHANNEL_WAVELENGTHS_NM.r] as const;

/** A channel value at λ: linear between the channels' dominant wavelengths, constant beyond. */
function channelLerp([r, g, b]: LinearRgb, l: number): number {
  const [wb, wg, wr] = CHANNEL_NM;
  if (l <= wb) return b;
  if (l >= wr) return r;
  return l <= wg ? b + ((g - b) * (l - wb)) / (wg - wb) : g + ((r - g) * (l - wg)) / (wr - wg);
}

/**
 * The knots' r from the base colour: the spectrum channelLerp makes of knot values (r, g, b) has,
 * under D65 with the white normalisation, linear sRGB (eqs (15)–(19)) linear in them; this is the
 * inverse of that 3×3 map, so the bare metal's colour at normal incidence is the base colour
 * wherever the knots come out in [0, ARTIST_METAL_MAX_REFLECTIVITY] (they are clamped there).
 */
const CHANNEL_KNOTS_FROM_RGB: Matrix3 = (() => {
  const w = spectralWeights('D65', 'white');
  const column = (unit: LinearRgb) => {
    const xyz = [w.x, w.y, w.z].map((t) =>
      t.reduce((sum, v, i) => sum + v * channelLerp(unit, LAMBDA_MIN_NM + i) * (i === 0 || i === t.length - 1 ? 0.5 : 1), 0),
    );
    return applyMatrix3(XYZ_TO_LINEAR_SRGB, xyz as unknown as LinearRgb);
  };
  const [cr, cg, cb] = [column([1, 0, 0]), column([0, 1, 0]), column([0, 0, 1])];
  return invert3([cr[0], cg[0], cb[0], cr[1], cg[1], cb[1], cr[2], cg[2], cb[2]]);
})();

/** The spacing of the medium's knots (nm): as fine as the shaders' own knots (src/film/filmMedia.ts), so their lerp of n, k adds nothing. */
const KNOT_STEP_NM = 5;
/** The knots span the colour band: 380–830 nm. */
const KNOTS_NM = { min: 380, max: 830 } as const;

/**
 * The metal as a medium from its base colour (F0, linear sRGB) and edge tint. r and g are each taken
 * linear in λ between the channels' dominant wavelengths (blue, green, red) and constant beyond,
 * r's three values chosen (CHANNEL_KNOTS_FROM_RGB) so that the bare metal under D65 shows the base
 * colour; ñ(λ) is the remapping of r(λ), g(λ), given every KNOT_STEP_NM (sampledIndex.ts), so the
 * bare metal's normal-incidence R(λ) is that piecewise-linear r(λ). An approximation: three numbers
 * stand for a spectrum (docs/material.md#a-metal-from-its-colour).
 */
export function artistMetalMedium(reflectivity: LinearRgb, edgeTint: LinearRgb): SampledIndex {
  const r = applyMatrix3(CHANNEL_KNOTS_FROM_RGB, reflectivity);
  const sampled: (readonly [number, number, number])[] = [];
  for (let l = KNOTS_NM.min; l <= KNOTS_NM.max; l += KNOT_STEP_NM) {
    const z = artistMetalIndex(channelLerp(r, l), channelLerp(edgeTint, l));
    sampled.push([l, z.re, z.im]);
  }
  return { sampled };
}

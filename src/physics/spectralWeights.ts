import { CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, CIE1931_XBAR, CIE1931_YBAR, CIE1931_ZBAR } from './data/cie1931Cmf2deg.ts';
import {
  type BasisIndex,
  type IlluminantSpec,
  basisSpectrum,
  illuminantKey,
  illuminantLines,
  illuminantSpd,
  tintSpectrum,
} from './illuminants.ts';
import { type LightTint, WHITE_TINT, lightTintText } from './lightTint.ts';
import { type SpectralLine } from './lightLines.ts';
import { interpolateTable } from './tableInterpolation.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM, type Normalization } from './spectralConventions.ts';

export { LAMBDA_MAX_NM, LAMBDA_MIN_NM, LAMBDA_SPAN_NM, NORMALIZATIONS, type Normalization } from './spectralConventions.ts';

export type Xyz = readonly [number, number, number];

/**
 * I_in(λ)·T(λ)·x̄, ȳ, z̄(λ) / k at every 1 nm from 380 to 830 nm (451 knots; between knots the
 * weights are linear), T the spectrum of the light's tint (1 untinted). These are the tables the
 * shader receives as a texture.
 */
export interface SpectralWeights {
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly z: Float64Array;
  /**
   * A line source's lines (lightLines.ts), each with p x̄, ȳ, z̄(λ_l) / k: the colour is the sum
   * Σ R(λ_l) · weight over them, and the tables above are 0. Absent for a light with a spectrum.
   */
  readonly lines?: readonly WeightedLine[];
}

/** A line at `nm` and its weights p x̄, ȳ, z̄(λ) / k. */
export interface WeightedLine {
  readonly nm: number;
  readonly x: number;
  readonly y: number;
  readonly z: number;
}

const cmf = (t: readonly number[], l: number) => interpolateTable(t, CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, l);

/**
 * The weights of a line source: p T(λ_l) x̄, ȳ, z̄(λ_l) / k with the CMFs linear between their 1 nm
 * knots and T the tint's spectrum. `white`: k = Σ p ȳ(λ_l), so a perfect reflector in the untinted
 * light has Y = 1. `paper`: the powers scaled to sum to 1 (a line has no value at 560 nm to scale
 * by) and the paper's k = ∫ ȳ dλ.
 */
function lineWeights(lines: readonly SpectralLine[], normalization: Normalization, tint: (lambdaNm: number) => number): SpectralWeights {
  const total = lines.reduce((sum, l) => sum + l.power, 0);
  const k =
    normalization === 'paper'
      ? total * trapezoid1nm((l) => cmf(CIE1931_YBAR, l))
      : lines.reduce((sum, l) => sum + l.power * cmf(CIE1931_YBAR, l.nm), 0);
  const weighted = lines.map((l) => {
    const p = (l.power * tint(l.nm)) / k;
    return { nm: l.nm, x: p * cmf(CIE1931_XBAR, l.nm), y: p * cmf(CIE1931_YBAR, l.nm), z: p * cmf(CIE1931_ZBAR, l.nm) };
  });
  const n = LAMBDA_SPAN_NM + 1;
  return { x: new Float64Array(n), y: new Float64Array(n), z: new Float64Array(n), lines: weighted };
}

const weightsCache = new Map<string, SpectralWeights>();
/** Weights kept (11 kB each): a CCT slider dragged for an hour must not grow the cache without end. */
const MAX_CACHED_WEIGHTS = 64;

/**
 * The weights of eqs (15)–(18) for an illuminant, normalisation and tint (the last 64 used are
 * cached). `white` divides by the untinted light's Y, so a tint darkens as well as colours the light.
 * `basis` j: the light times basis spectrum j as well (a column of environmentMatrix.ts's M).
 */
export function spectralWeights(
  illuminant: IlluminantSpec,
  normalization: Normalization = 'white',
  tint: LightTint = WHITE_TINT,
  basis: BasisIndex | null = null,
): SpectralWeights {
  const key = `${illuminantKey(illuminant)}|${normalization}|${lightTintText(tint)}|${basis ?? ''}`;
  const cached = weightsCache.get(key);
  if (cached) {
    weightsCache.delete(key); // most recently used last
    weightsCache.set(key, cached);
    return cached;
  }
  const lines = illuminantLines(illuminant);
  const tinted = tintSpectrum(tint);
  const b = basis === null ? null : basisSpectrum(basis);
  const t = b === null ? tinted : (l: number) => tinted(l) * b(l);
  const w = lines === null ? spectrumWeights(illuminant, normalization, t) : lineWeights(lines, normalization, t);
  weightsCache.set(key, w);
  if (weightsCache.size > MAX_CACHED_WEIGHTS) weightsCache.delete(weightsCache.keys().next().value!);
  return w;
}

/**
 * What a light's weights, and so its spectral transform and bins, depend on. `basis` j: the light
 * times basis spectrum j, the light of column j of a film's environment matrix (a plane of its
 * colour: environmentMatrix.ts); absent for the light itself.
 */
export interface SpectralLight {
  readonly illuminant: IlluminantSpec;
  readonly normalization: Normalization;
  readonly lightTint: LightTint;
  readonly basis?: BasisIndex;
}

/** The weights of `light`: spectralWeights of its illuminant, normalisation, tint and basis. */
export const lightWeights = (light: SpectralLight): SpectralWeights =>
  spectralWeights(light.illuminant, light.normalization, light.lightTint, light.basis ?? null);

/** How many colour planes a film is computed in: its XYZ (1), or its environment matrix, a column per basis spectrum (3). */
export type PlaneCount = 1 | 3;

/**
 * The light a film's colour planes are computed under: the light itself for its XYZ (1); the untinted
 * light for its environment matrix (3), which takes a tint t as one more colour it maps (M t), so
 * that a change of tint changes no plane.
 */
export const planesLight = (light: SpectralLight, planes: PlaneCount): SpectralLight =>
  planes === 1 ? light : { ...light, lightTint: WHITE_TINT };

/** The lights of a film's colour planes: the light itself (1), or the untinted light times each basis spectrum (3). */
export const planeLights = (light: SpectralLight, planes: PlaneCount): SpectralLight[] =>
  planes === 1 ? [light] : ([0, 1, 2] as const).map((basis) => ({ ...planesLight(light, planes), basis }));

/** The weights of a light with a spectrum, I_in T x̄, ȳ, z̄ / k at its 1 nm knots (T the tint's spectrum). */
function spectrumWeights(illuminant: IlluminantSpec, normalization: Normalization, tint: (lambdaNm: number) => number): SpectralWeights {
  const spd = illuminantSpd(illuminant);
  const n = LAMBDA_SPAN_NM + 1;
  const x = new Float64Array(n);
  const y = new Float64Array(n);
  const z = new Float64Array(n);
  const scale = normalization === 'paper' ? 1 / spd(560) : 1;
  for (let i = 0; i < n; i++) {
    const l = LAMBDA_MIN_NM + i;
    const s = spd(l) * scale * tint(l);
    x[i] = s * cmf(CIE1931_XBAR, l);
    y[i] = s * cmf(CIE1931_YBAR, l);
    z[i] = s * cmf(CIE1931_ZBAR, l);
  }
  // k by the same trapezoid rule as the colour integral, so a perfect reflector in the untinted light gives Y = 1 exactly.
  const k = normalization === 'paper' ? trapezoid1nm((l) => cmf(CIE1931_YBAR, l)) : trapezoid1nm((l) => spd(l) * cmf(CIE1931_YBAR, l));
  for (const t of [x, y, z]) for (let i = 0; i < n; i++) t[i] = (t[i] as number) / k;
  return { x, y, z };
}

/** ∫ f dλ over the integration range by the trapezoid rule on its 1 nm knots. */
function trapezoid1nm(f: (lambdaNm: number, i: number) => number): number {
  let sum = 0;
  for (let i = 0; i <= LAMBDA_SPAN_NM; i++) sum += f(LAMBDA_MIN_NM + i, i) * (i === 0 || i === LAMBDA_SPAN_NM ? 0.5 : 1);
  return sum;
}

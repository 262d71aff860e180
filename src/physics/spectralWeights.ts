import { CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, CIE1931_XBAR, CIE1931_YBAR, CIE1931_ZBAR } from './data/cie1931Cmf2deg.ts';
import { type IlluminantSpec, illuminantKey, illuminantSpd, interpolateTable } from './illuminants.ts';
import { LAMBDA_MIN_NM, LAMBDA_SPAN_NM, type Normalization } from './spectralConventions.ts';

export { LAMBDA_MAX_NM, LAMBDA_MIN_NM, LAMBDA_SPAN_NM, NORMALIZATIONS, type Normalization } from './spectralConventions.ts';

export type Xyz = readonly [number, number, number];

/**
 * I_in(λ)·x̄, ȳ, z̄(λ) / k at every 1 nm from 380 to 830 nm (451 knots; between knots the
 * weights are linear). These are the tables the shader receives as a texture.
 */
export interface SpectralWeights {
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly z: Float64Array;
}

const weightsCache = new Map<string, SpectralWeights>();
/** Weights kept (11 kB each): a CCT slider dragged for an hour must not grow the cache without end. */
const MAX_CACHED_WEIGHTS = 64;

/** The weights of eqs (15)–(18) for an illuminant and normalisation (the last 64 used are cached). */
export function spectralWeights(illuminant: IlluminantSpec, normalization: Normalization = 'white'): SpectralWeights {
  const key = `${illuminantKey(illuminant)}|${normalization}`;
  const cached = weightsCache.get(key);
  if (cached) {
    weightsCache.delete(key); // most recently used last
    weightsCache.set(key, cached);
    return cached;
  }
  const spd = illuminantSpd(illuminant);
  const n = LAMBDA_SPAN_NM + 1;
  const cmf = (t: readonly number[], l: number) => interpolateTable(t, CIE1931_CMF_START_NM, CIE1931_CMF_STEP_NM, l);
  const x = new Float64Array(n);
  const y = new Float64Array(n);
  const z = new Float64Array(n);
  const scale = normalization === 'paper' ? 1 / spd(560) : 1;
  for (let i = 0; i < n; i++) {
    const l = LAMBDA_MIN_NM + i;
    const s = spd(l) * scale;
    x[i] = s * cmf(CIE1931_XBAR, l);
    y[i] = s * cmf(CIE1931_YBAR, l);
    z[i] = s * cmf(CIE1931_ZBAR, l);
  }
  // k by the same trapezoid rule as the colour integral, so a perfect reflector gives Y = 1 exactly.
  const k = normalization === 'paper' ? trapezoid1nm((l) => cmf(CIE1931_YBAR, l)) : trapezoid1nm((_, i) => y[i] as number);
  for (const t of [x, y, z]) for (let i = 0; i < n; i++) t[i] = (t[i] as number) / k;
  const w = { x, y, z };
  weightsCache.set(key, w);
  if (weightsCache.size > MAX_CACHED_WEIGHTS) weightsCache.delete(weightsCache.keys().next().value!);
  return w;
}

/** ∫ f dλ over the integration range by the trapezoid rule on its 1 nm knots. */
function trapezoid1nm(f: (lambdaNm: number, i: number) => number): number {
  let sum = 0;
  for (let i = 0; i <= LAMBDA_SPAN_NM; i++) sum += f(LAMBDA_MIN_NM + i, i) * (i === 0 || i === LAMBDA_SPAN_NM ? 0.5 : 1);
  return sum;
}

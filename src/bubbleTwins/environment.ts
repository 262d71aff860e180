import type { Rgb } from '../physics/colorConversions.ts';
import type { EnvironmentPixels } from '../bubbleMaterials/environmentMaps.ts';
import type { EnvironmentColor } from '../environments/environmentColor.ts';

type Vec3 = readonly [number, number, number];

/**
 * What a view's walls reflect and its background shows (twin of shaders/bubbleMaterials/environment.glsl),
 * by its kind (ENVIRONMENT_KINDS, src/environments/environments.ts): `none` black, `sky` the procedural sky, an
 * HDR `map` turned about the vertical axis, or one `color` from every direction.
 */
export type ShownEnvironment =
  | { readonly kind: 'none' }
  | { readonly kind: 'sky' }
  | { readonly kind: 'map'; readonly pixels: EnvironmentPixels; readonly rotationDeg: number }
  | { readonly kind: 'color'; readonly color: EnvironmentColor };

const clamp01 = (v: number) => Math.min(1, Math.max(0, v));
const smoothstep = (e0: number, e1: number, x: number) => {
  const t = clamp01((x - e0) / (e1 - e0));
  return t * t * (3 - 2 * t);
};
const mix = (a: Rgb, b: Rgb, t: number): Rgb => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t];

/** The procedural sky: a blue zenith over a pale horizon, a dark green ground (linear sRGB), from a direction's height y ∈ [−1, 1]. */
function skyRadiance(y: number): Rgb {
  return y >= 0
    ? mix([0.6, 0.7, 0.8], [0.1, 0.25, 0.6], smoothstep(0, 0.8, y))
    : mix([0.2, 0.22, 0.16], [0.05, 0.08, 0.04], smoothstep(0, -0.6, y));
}

/**
 * The equirectangular map's texture coordinates of a unit direction, the map turned by
 * `rotationDeg` about +y (a feature at azimuth φ moves to φ + rotation): three.js's equirectUv
 * (u from atan(z, x), v = 1 straight up) of the direction turned back.
 */
export function equirectUv(d: Vec3, rotationDeg: number): [number, number] {
  const a = (rotationDeg * Math.PI) / 180;
  const c = Math.cos(a),
    s = Math.sin(a);
  const x = c * d[0] - s * d[2],
    z = s * d[0] + c * d[2];
  return [Math.atan2(z, x) / (2 * Math.PI) + 0.5, Math.asin(Math.max(-1, Math.min(1, d[1]))) / Math.PI + 0.5];
}

/** A bilinear texel lookup as the GPU filters: texel centres at (i + ½)/size, u wrapping round, v clamped. */
function sampleBilinear(p: EnvironmentPixels, u: number, v: number): Rgb {
  const fx = u * p.width - 0.5,
    fy = Math.min(p.height - 1, Math.max(0, v * p.height - 0.5));
  const x0 = Math.floor(fx),
    y0 = Math.floor(fy);
  const tx = fx - x0,
    ty = fy - y0;
  const wrap = (x: number) => ((x % p.width) + p.width) % p.width;
  const y1 = Math.min(p.height - 1, y0 + 1);
  const texel = (x: number, y: number, k: number) => p.rgba[4 * (y * p.width + wrap(x)) + k]!;
  const channel = (k: number) =>
    (1 - ty) * ((1 - tx) * texel(x0, y0, k) + tx * texel(x0 + 1, y0, k)) + ty * ((1 - tx) * texel(x0, y1, k) + tx * texel(x0 + 1, y1, k));
  return [channel(0), channel(1), channel(2)];
}

/** The environment's linear sRGB radiance arriving from `direction` (any length). */
export function environmentRadiance(direction: Vec3, env: ShownEnvironment): Rgb {
  if (env.kind === 'none') return [0, 0, 0];
  if (env.kind === 'color') return [env.color[0], env.color[1], env.color[2]];
  const l = Math.hypot(direction[0], direction[1], direction[2]);
  const d: Vec3 = [direction[0] / l, direction[1] / l, direction[2] / l];
  if (env.kind === 'sky') return skyRadiance(d[1]);
  const [u, v] = equirectUv(d, env.rotationDeg);
  return sampleBilinear(env.pixels, u, v);
}

/** The light a wall reflects from the mirror direction: the illuminant's white with `none` (the reference views), else the environment. */
export const reflectedRadiance = (direction: Vec3, env: ShownEnvironment): Rgb =>
  env.kind === 'none' ? [1, 1, 1] : environmentRadiance(direction, env);

import { differenceCiede2000 } from 'culori';
import type { Xyz } from './spectralWeights.ts';

/**
 * CIELAB (CIE 015:2018 §8.2.1) of a colour relative to a reference white (normally the
 * illuminant's own XYZ, so the colour is judged as adapted to its light).
 */
export function xyzToLab([X, Y, Z]: Xyz, [Xn, Yn, Zn]: Xyz): { l: number; a: number; b: number } {
  const e = 216 / 24389;
  const k = 24389 / 27;
  const f = (t: number) => (t > e ? Math.cbrt(t) : (k * t + 16) / 116);
  const fx = f(X / Xn),
    fy = f(Y / Yn),
    fz = f(Z / Zn);
  return { l: 116 * fy - 16, a: 500 * (fx - fy), b: 200 * (fy - fz) };
}

const ciede2000 = differenceCiede2000();

/** ΔE00 (CIEDE2000, by culori) between two XYZ colours seen under the same white. */
export function deltaE00(a: Xyz, b: Xyz, white: Xyz): number {
  return ciede2000({ mode: 'lab65', ...xyzToLab(a, white) }, { mode: 'lab65', ...xyzToLab(b, white) });
}

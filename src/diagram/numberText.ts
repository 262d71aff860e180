import type { Complex } from '../physics/complex.ts';

/** A value to 4 significant figures, as the diagram states R and the amplitudes (`0.1216`, `1.200e-7`). */
export const fourFigures = (x: number): string => (x === 0 ? '0' : Math.abs(x) < 1e-4 ? x.toExponential(3) : x.toPrecision(4));

/** A setting as it was given, without trailing noise (`1.33`, `30`, `12.5`). */
export const settingText = (x: number): string => String(+x.toFixed(4));

/** A complex number to 4 significant figures: `0.1416 − 0.0200i`. */
export function complexText(z: Complex): string {
  if (z.im === 0) return fourFigures(z.re);
  const im = `${fourFigures(Math.abs(z.im))}i`;
  if (z.re === 0) return z.im < 0 ? `−${im}` : im;
  return `${fourFigures(z.re)} ${z.im < 0 ? '−' : '+'} ${im}`;
}

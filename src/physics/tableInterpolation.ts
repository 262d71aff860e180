/**
 * How the CIE's tables are read between their rows: linearly (CIE 015's rule for daylight, and
 * the one the reference keeps for every table). A module of its own, free of the tables, so that
 * a Web Worker given a light's weights needs no light's data.
 */

/** Linear interpolation in a table sampled every `stepNm` from `startNm` (CIE's rule for daylight). */
export function interpolateTable(table: ArrayLike<number>, startNm: number, stepNm: number, lambdaNm: number): number {
  const u = (lambdaNm - startNm) / stepNm;
  const i = Math.min(Math.max(Math.floor(u), 0), table.length - 2);
  const f = u - i;
  return (table[i] as number) * (1 - f) + (table[i + 1] as number) * f;
}

import { type Complex } from './complex.ts';
import { monotoneCubic } from './monotoneCubic.ts';

/** One row of a published table: [λ in µm, n, k], ñ = n + ik. */
export type NkRow = readonly [lambdaUm: number, n: number, k: number];
/** A table's rows, λ strictly ascending. */
export type NkTable = readonly NkRow[];

/** hc/e in eV·nm (exact in the 2019 SI, to 13 digits): photon energy E = HC_EV_NM / λ. */
export const HC_EV_NM = 1239.841984332;

/** A tabulated medium: ñ(λ) between its first and last rows, and that range. */
export interface TabulatedIndex {
  readonly indexAt: (lambdaNm: number) => Complex;
  readonly rangeNm: { readonly min: number; readonly max: number };
}

/**
 * ñ(λ) from a table: n and k each interpolated by a monotone cubic (monotoneCubic.ts) in photon
 * energy, the variable the tables were measured in (Johnson and Christy: fixed energies ~0.12 eV
 * apart). Exact at every row; between rows n and k stay between their neighbours' values, so k ≥ 0
 * and n > 0 wherever the table says so (docs/physics.md#interpolating-the-tables).
 */
export function tabulatedIndex(table: NkTable): TabulatedIndex {
  const rows = [...table].reverse(); // energy ascending
  // λ in nm as a decimal number (0.5486 µm → 548.6), so asking for a row's own λ hits its node exactly.
  const nm = (lambdaUm: number) => Number((lambdaUm * 1000).toPrecision(12));
  const energies = rows.map(([lambdaUm]) => HC_EV_NM / nm(lambdaUm));
  const n = monotoneCubic(
    energies,
    rows.map((r) => r[1]),
  );
  const k = monotoneCubic(
    energies,
    rows.map((r) => r[2]),
  );
  const rangeNm = { min: nm(table[0]![0]), max: nm(table[table.length - 1]![0]) };
  return {
    indexAt: (lambdaNm) => {
      const e = HC_EV_NM / lambdaNm;
      return { re: n(e), im: k(e) };
    },
    rangeNm,
  };
}

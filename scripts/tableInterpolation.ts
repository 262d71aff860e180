/**
 * `npm run table-interpolation`: how well the monotone cubic (src/physics/monotoneCubic.ts, in photon
 * energy) reproduces the published tables of src/physics/data. For each table: the largest |Δn|,
 * |Δk| at its own rows (0 when the interpolant passes through them) and leave-one-out (each inner
 * row dropped in turn and predicted from the rest: a bound on the error between rows, where the
 * true curve is not known, with twice the row spacing). Prints Markdown for docs/physics.md.
 */
import { JOHNSON_CHRISTY_1972 } from '../src/physics/data/johnsonChristy1972.ts';
import { JOHNSON_CHRISTY_1974 } from '../src/physics/data/johnsonChristy1974.ts';
import { QUERRY_1985 } from '../src/physics/data/querry1985.ts';
import { SARKAR_2019 } from '../src/physics/data/sarkar2019.ts';
import { asComplex } from '../src/physics/complex.ts';
import { type NamedMedium, namedIndex } from '../src/physics/namedMedia.ts';
import { type NkTable, tabulatedIndex } from '../src/physics/tabulatedIndex.ts';

const TABLES: [NamedMedium, NkTable][] = [
  ['Au', JOHNSON_CHRISTY_1972.Au],
  ['Ag', JOHNSON_CHRISTY_1972.Ag],
  ['Cu', JOHNSON_CHRISTY_1972.Cu],
  ['Ti', JOHNSON_CHRISTY_1974.Ti],
  ['Fe', JOHNSON_CHRISTY_1974.Fe],
  ['Cr', JOHNSON_CHRISTY_1974.Cr],
  ['Ni', JOHNSON_CHRISTY_1974.Ni],
  ['Fe3O4', QUERRY_1985.Fe3O4],
  ['TiO2', SARKAR_2019.TiO2],
];

const nm = (lambdaUm: number) => Number((lambdaUm * 1000).toPrecision(12));
const fmt = (x: number) => (x === 0 ? '0' : x.toExponential(1));

/** R of the bare medium seen from air at normal incidence, |(ñ − 1)/(ñ + 1)|²: what the error does to a colour. */
const bareR = (n: number, k: number) => ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k);

console.log('| table | rows | at rows: max abs Δn, Δk | leave-one-out: max abs Δn (at nm), Δk (at nm), ΔR of the bare medium |');
console.log('|---|---|---|---|');
for (const [name, rows] of TABLES) {
  const full = namedIndex(name);
  let atRows = 0;
  for (const [l, n, k] of rows) {
    const v = asComplex(full(nm(l)));
    atRows = Math.max(atRows, Math.abs(v.re - n), Math.abs(v.im - k));
  }
  let dn = 0,
    dk = 0,
    dR = 0,
    whereN = 0,
    whereK = 0;
  for (let i = 1; i + 1 < rows.length; i++) {
    const [l, n, k] = rows[i]!;
    const v = tabulatedIndex(rows.filter((_, j) => j !== i)).indexAt(nm(l));
    if (Math.abs(v.re - n) > dn) [dn, whereN] = [Math.abs(v.re - n), nm(l)];
    if (Math.abs(v.im - k) > dk) [dk, whereK] = [Math.abs(v.im - k), nm(l)];
    dR = Math.max(dR, Math.abs(bareR(v.re, v.im) - bareR(n, k)));
  }
  const at = (where: number) => (where === 0 ? '' : ` (${where})`);
  console.log(
    `| ${name} | ${rows.length} | ${fmt(atRows)} | ${dn.toFixed(3)}${at(whereN)}, ${dk.toFixed(3)}${at(whereK)}, ${dR.toFixed(4)} |`,
  );
}

/**
 * The colour tool with absorbing media (src/cli, docs/physics.md#absorbing-media), in-process
 * (`runColorCommand`). Expected values: the normal-incidence Fresnel formula of a bare absorbing
 * substrate, |(ñ − 1)/(ñ + 1)|², the published table rows (Johnson & Christy's gold at 548.6 nm,
 * Sarkar's TiO2 film at 550 nm) and the real-index output the tool already gives (k = 0).
 */
import { describe, expect, it } from 'vitest';
import { ALGEBRAIC_TOL, GOLD_GOLDEN_TOL } from '../tolerances.ts';
import { colorTool } from './cli/colorTool.ts';

type Index = number | { n: number; k: number };
interface Output {
  xyz: number[];
  reflectance: number[];
  nFilm: Index[];
  nInside: Index[];
}

const files: Record<string, string> = {
  complex: '[{ "id": "c", "nInside": { "complex": [2.6, 3.4] }, "thicknessNm": 0, "wavelengthsNm": [500] }]',
  'complex-film': '[{ "id": "f", "nFilm": { "complex": [2.2, 0.3] }, "nInside": "Au", "thicknessNm": 60, "wavelengthsNm": [550] }]',
  'negative-k': '[{ "id": "neg", "nInside": { "complex": [1, -0.5] } }]',
  'zero-n': '[{ "id": "zero", "nFilm": { "complex": [0, 2] } }]',
  'complex-outside': '[{ "id": "out", "nOutside": { "complex": [1.5, 0.1] } }]',
  'named-outside': '[{ "id": "out2", "nOutside": "Au" }]',
  'unknown-name': '[{ "id": "gold", "nInside": "gold" }]',
  'bad-pair': '[{ "id": "pair", "nInside": { "complex": [1] } }]',
};
const { run, ok } = colorTool<Output>(files);
const bareR = (n: number, k: number) => ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k);

describe('color CLI, absorbing media', () => {
  it('--help lists every named medium with its source and range', () => {
    const { stdout } = run('--help');
    expect(stdout).toMatch(/^ {2}water +water at 20 °C, Daimon & Masumura 2007 \(Sellmeier\), 182–1129 nm$/m);
    expect(stdout).toMatch(/^ {2}Au +gold, Johnson & Christy 1972, 367\.9–892 nm$/m);
    expect(stdout).toMatch(/^ {2}SiO2 +fused silica, Malitson 1965 \(Sellmeier\), 210–3710 nm$/m);
    for (const name of ['Ag', 'Cu', 'Al', 'Ti', 'Fe', 'Cr', 'Ni', 'TiO2', 'Fe3O4'])
      expect(stdout).toMatch(new RegExp(`^ {2}${name} +\\S`, 'm'));
  });

  it('--n-inside Au: bare gold at 548.6 nm reflects 0.786916 and reports ñ = 0.43 + 2.455i', () => {
    const [c] = ok('--n-inside', 'Au', '--thickness', '0', '--wavelengths', '548.6');
    expect(Math.abs(c!.reflectance[0]! - 0.786916)).toBeLessThan(GOLD_GOLDEN_TOL);
    expect(c!.nInside).toEqual([{ n: 0.43, k: 2.455 }]);
    expect(c!.nFilm).toEqual([1.33]);
  });

  it('--n-inside complex:2.6,3.4 and { "complex": [2.6, 3.4] } give the bare substrate its Fresnel R', () => {
    const [flag] = ok('--n-inside', 'complex:2.6,3.4', '--thickness', '0', '--wavelengths', '500');
    const [file] = ok('--cases', 'complex');
    for (const c of [flag!, file!]) {
      expect(Math.abs(c.reflectance[0]! - bareR(2.6, 3.4))).toBeLessThan(ALGEBRAIC_TOL);
      expect(c.nInside).toEqual([{ n: 2.6, k: 3.4 }]);
      // A constant R gives Y = R (Y = 1 for a perfect white reflector).
      expect(Math.abs(c.xyz[1]! - bareR(2.6, 3.4))).toBeLessThan(1e-9);
    }
  });

  it('--n-film TiO2 reports the film as a real number (k = 0): Sarkar et al. at 550 nm, 2.164358', () => {
    const [c] = ok('--n-film', 'TiO2', '--thickness', '120', '--wavelengths', '550');
    expect(c!.nFilm).toEqual([2.164358]);
    expect(c!.nInside).toEqual([1]);
  });

  it('complex:n,0 is the real index: the same output as the number', () => {
    const [real] = ok('--n-film', '1.9', '--n-inside', '1.5', '--thickness', '300', '--angle', '40', '--wavelengths', '450,600');
    const [zero] = ok(
      '--n-film',
      'complex:1.9,0',
      '--n-inside',
      'complex:1.5,0',
      '--thickness',
      '300',
      '--angle',
      '40',
      '--wavelengths',
      '450,600',
    );
    expect(zero).toEqual(real);
  });

  it('an absorbing film on gold from a cases file: nFilm { n, k } and R in [0, 1]', () => {
    const [c] = ok('--cases', 'complex-film');
    expect(c!.nFilm).toEqual([{ n: 2.2, k: 0.3 }]);
    expect(c!.reflectance[0]).toBeGreaterThan(0);
    expect(c!.reflectance[0]).toBeLessThan(1);
  });

  it('a CSV table carries n and k of the film and the inside', () => {
    const r = run('--n-inside', 'Ag', '--from', '0', '--to', '20', '--step', '10', '--format', 'csv', '--wavelengths', '548.6');
    expect(r.exitCode).toBe(0);
    const [header, first] = r.stdout.trim().split('\n') as [string, string];
    const cols = header.split(',');
    const row = first.split(',');
    expect(row[cols.indexOf('nInside_548.6nm')]).toBe('0.06');
    expect(row[cols.indexOf('kInside_548.6nm')]).toBe('3.586');
    expect(row[cols.indexOf('kFilm_548.6nm')]).toBe('0');
  });

  const refused: [args: string[], parameter: string, says: string][] = [
    [['--n-inside', 'complex:1,-0.5'], '--n-inside', 'k is -0.5, below 0'],
    [['--n-film', 'complex:0,2'], '--n-film', 'n is 0, below 0.01'],
    [['--n-film', 'complex:-1,2'], '--n-film', 'n is -1, below 0.01'],
    [['--n-inside', 'gold'], '--n-inside', 'Au, Ag, Cu, Al, Ti, Fe, Cr, Ni, TiO2, Fe3O4, SiO2'],
    [['--n-inside', 'complex:1,2,3'], '--n-inside', 'complex:n,k'],
    [['--n-outside', 'complex:1.5,0.1'], '--n-outside', 'the outside is transparent'],
    [['--n-outside', 'Au'], '--n-outside', 'the outside is transparent'],
    [['--n-inside', 'Au', '--wavelengths', '300'], '--wavelengths[0]', '[367.9, 830] nm (where nInside Au has data)'],
    [['--cases', 'negative-k'], 'nInside', 'k is -0.5, below 0'],
    [['--cases', 'zero-n'], 'nFilm', 'n is 0, below 0.01'],
    [['--cases', 'complex-outside'], 'nOutside', 'the outside is transparent'],
    [['--cases', 'named-outside'], 'nOutside', 'the outside is transparent'],
    [['--cases', 'unknown-name'], 'nInside', 'complex:n,k'],
    [['--cases', 'bad-pair'], 'nInside', 'complex:n,k'],
  ];
  it.each(refused)('%j → exit 2, one line naming %s and saying %s', (args, parameter, says) => {
    const r = run(...args);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(`${parameter}: `);
    expect(r.stderr).toContain(says);
    expect(r.stderr.length).toBeLessThan(400);
  });
});

/**
 * The colour tool with a stack of films (`--layers`, a case's `layers`), in-process
 * (`runColorCommand`). Expected values: the admittance of a quarter-wave stack at its design
 * wavelength (Macleod, Thin-Film Optical Filters §5.2: Y = (n_H/n_L)^{2N} n_s, R = ((n_0 − Y)/(n_0 + Y))²),
 * and the tool's own single-film output for a stack of one layer (an independent identity: the
 * transfer matrix of one layer is eq (13)).
 */
import { describe, expect, it } from 'vitest';
import { ALGEBRAIC_TOL, TMM_TOL } from '../../tolerances.ts';
import { colorTool } from './colorTool.ts';

type Index = number | { n: number; k: number };
interface Output {
  id: string | number;
  xyz: number[];
  reflectance: number[];
  nFilm?: Index[];
  nLayers?: Index[][];
  nInside: Index[];
}

const files: Record<string, string> = {
  one: JSON.stringify([
    { id: 'film', nFilm: 'TiO2', thicknessNm: 180, angleDeg: 30, nInside: 1.52, polarization: 's', wavelengthsNm: [450, 600] },
    { id: 'stack', layers: [{ n: 'TiO2', thicknessNm: 180 }], angleDeg: 30, nInside: 1.52, polarization: 's', wavelengthsNm: [450, 600] },
  ]),
  mirror: JSON.stringify([
    {
      id: 'm',
      layers: Array.from({ length: 16 }, (_, i) => (i % 2 === 0 ? { n: 2.5, thicknessNm: 53.2 } : { n: 1.4, thicknessNm: 95 })),
      wavelengthsNm: [532],
    },
  ]),
  'with-nFilm': '[{ "id": "a", "layers": [{ "n": 1.5, "thicknessNm": 100 }], "nFilm": 1.4 }]',
  'with-thickness': '[{ "id": "b", "layers": [{ "n": 1.5, "thicknessNm": 100 }], "thicknessNm": 100 }]',
  'field-thickness': '[{ "id": "c", "layers": [{ "n": 1.5, "thicknessNm": "d" }] }]',
  'not-array': '[{ "id": "e", "layers": "1.5:100" }]',
  empty: '[{ "id": "f", "layers": [] }]',
  'too-many': JSON.stringify([{ id: 'g', layers: Array.from({ length: 65 }, () => ({ n: 1.5, thicknessNm: 10 })) }]),
  'no-n': '[{ "id": "h", "layers": [{ "thicknessNm": 100 }] }]',
  'extra-key': '[{ "id": "i", "layers": [{ "n": 1.5, "thicknessNm": 100, "k": 0 }] }]',
  'bad-medium': '[{ "id": "j", "layers": [{ "n": 1.5, "thicknessNm": 100 }, { "n": "unobtainium", "thicknessNm": 100 }] }]',
  'bad-index': '[{ "id": "k", "layers": [{ "n": 9, "thicknessNm": 100 }] }]',
  'bad-thickness': '[{ "id": "l", "layers": [{ "n": 1.5, "thicknessNm": 20001 }] }]',
  'media-in-json': JSON.stringify([
    {
      id: 'media',
      layers: [
        { n: 'water', thicknessNm: 100 },
        { n: { cauchy: [1.45, 6000] }, thicknessNm: 50 },
        { n: { complex: [0.2, 3.4] }, thicknessNm: 5 },
        { n: 'TiO2', thicknessNm: 40 },
      ],
      wavelengthsNm: [550],
    },
  ]),
};
const { run, ok } = colorTool<Output>(files);
const refused = (args: string[], ...words: string[]) => {
  const r = run(...args);
  expect(r.exitCode, args.join(' ')).toBe(2);
  expect(r.stdout).toBe('');
  for (const w of words) expect(r.stderr, args.join(' ')).toContain(w);
};

describe('color CLI, a stack of films', () => {
  it('a quarter-wave mirror (HL)^8 reflects at its design wavelength what its admittance says', () => {
    const [nH, nL, pairs] = [2.5, 1.4, 8];
    const y = (nH / nL) ** (2 * pairs); // on n_s = 1, the default inside
    const expected = ((1 - y) / (1 + y)) ** 2;
    const [fromFlag] = ok('--layers', '(2.5:53.2/1.4:95)*8', '--wavelengths', '532');
    expect(Math.abs(fromFlag!.reflectance[0]! - expected)).toBeLessThan(TMM_TOL);
    expect(fromFlag!.nLayers).toEqual([Array.from({ length: 16 }, (_, i) => (i % 2 === 0 ? nH : nL))]);
    expect(fromFlag).not.toHaveProperty('nFilm');
    const [fromFile] = ok('--cases', 'mirror');
    expect(fromFile!.xyz).toEqual(fromFlag!.xyz);
    expect(fromFile!.reflectance).toEqual(fromFlag!.reflectance);
  });

  it('a stack of one layer gives the single film its xyz and R, from a cases file and from the flags', () => {
    const [film, stack] = ok('--cases', 'one');
    stack!.xyz.forEach((v, i) => expect(Math.abs(v - film!.xyz[i]!)).toBeLessThan(ALGEBRAIC_TOL));
    stack!.reflectance.forEach((v, i) => expect(Math.abs(v - film!.reflectance[i]!)).toBeLessThan(ALGEBRAIC_TOL));
    expect(stack!.nLayers!.map((atLambda) => atLambda[0])).toEqual(film!.nFilm);
    const common = ['--angle', '30', '--n-inside', '1.52', '--polarization', 's', '--wavelengths', '450,600'];
    const [flagStack] = ok('--layers', 'TiO2:d', '--thickness', '180', ...common);
    const [flagFilm] = ok('--n-film', 'TiO2', '--thickness', '180', ...common);
    flagStack!.xyz.forEach((v, i) => expect(Math.abs(v - flagFilm!.xyz[i]!)).toBeLessThan(ALGEBRAIC_TOL));
    expect(flagStack!.xyz).toEqual(stack!.xyz);
  });

  it('takes every medium a film takes, as JSON in a case and as text in --layers', () => {
    const [fromFile] = ok('--cases', 'media-in-json');
    const [fromFlag] = ok('--layers', 'water:100/cauchy:1.45,6000:50/complex:0.2,3.4:5/TiO2:40', '--wavelengths', '550');
    expect(fromFlag).toEqual({ ...fromFile, id: 0 });
    expect(fromFile!.nLayers![0]![2]).toEqual({ n: 0.2, k: 3.4 });
    expect(fromFile!.reflectance[0]).toBeGreaterThan(0);
    expect(fromFile!.reflectance[0]).toBeLessThan(1);
  });

  it('a thickness table varies the d layers: row d of `1.46:d/TiO2:50` is the case with --thickness d', () => {
    const table = run('--layers', '1.46:d/TiO2:50', '--from', '0', '--to', '200', '--step', '100', '--wavelengths', '500');
    expect(table.exitCode).toBe(0);
    const rows = JSON.parse(table.stdout) as (Output & { thicknessNm: number })[];
    expect(rows.map((r) => r.thicknessNm)).toEqual([0, 100, 200]);
    const [single] = ok('--layers', '1.46:d/TiO2:50', '--thickness', '100', '--wavelengths', '500');
    expect(rows[1]!.xyz).toEqual(single!.xyz);
    // d = 0 leaves TiO2 alone on the inside: one layer, the paper's film, to the rounding of the recursion.
    const [bare] = ok('--layers', 'TiO2:50', '--wavelengths', '500');
    rows[0]!.xyz.forEach((v, i) => expect(Math.abs(v - bare!.xyz[i]!)).toBeLessThan(ALGEBRAIC_TOL));
  });

  it("a CSV table names each layer's n and k columns, outside in", () => {
    const r = run('--layers', '1.46:d/TiO2:50', '--from', '0', '--to', '10', '--step', '10', '--wavelengths', '500', '--format', 'csv');
    expect(r.exitCode).toBe(0);
    const [header, first] = r.stdout.trim().split('\n');
    const columns = header!.split(',');
    expect(columns.slice(-6)).toEqual([
      'nLayer1_500nm',
      'kLayer1_500nm',
      'nLayer2_500nm',
      'kLayer2_500nm',
      'nInside_500nm',
      'kInside_500nm',
    ]);
    expect(columns).not.toContain('nFilm_500nm');
    const cells = first!.split(',');
    expect(cells).toHaveLength(columns.length);
    expect(Number(cells[columns.indexOf('nLayer1_500nm')])).toBe(1.46);
  });

  it.each<[string[], string[]]>([
    [['--layers', '1.5:100', '--n-film', '1.4'], ['--layers: not allowed with --n-film']],
    [['--layers', '1.5:100', '--thickness', '100'], ['--thickness: not allowed with --layers that has no d layer']],
    [['--layers', '1.5:100', '--from', '0', '--to', '10', '--step', '5'], ['not allowed with --from/--to/--step without a d layer']],
    [['--layers', '(1.5:100'], ['--layers: "(1.5:100" is not allowed (unbalanced parentheses']],
    [['--layers', '(1.5:1)*65'], ['not an integer in [1, 64]']],
    [['--layers', '(1.5:1)*64/1.5:1'], ['more than 64 layers after repetition']],
    [['--layers', 'bogus:1'], ['not a medium a film takes']],
    [['--layers', '1.5:-1'], ['is not a number in [0, 20000] nm or d']],
    [['--layers', ''], ['--layers: "" is not allowed (no layers)']],
    [['--layers', '1.5:100', '--cases', 'one'], ['--layers: not allowed with --cases']],
    [['--cases', 'with-nFilm'], ['case "a" (index 0): layers: not allowed with nFilm']],
    [['--cases', 'with-thickness'], ['case "b" (index 0): layers: not allowed with thicknessNm']],
    [
      ['--cases', 'field-thickness'],
      ['layers[0].thicknessNm: "d" is not allowed', "a case's layers have their own thicknesses"],
    ],
    [['--cases', 'not-array'], ['layers: "1.5:100" is not allowed; expected an array of 1 to 64 objects']],
    [['--cases', 'empty'], ['layers: [] is not allowed; expected an array of 1 to 64 objects']],
    [['--cases', 'too-many'], ['expected an array of 1 to 64 objects']],
    [['--cases', 'no-n'], ['layers[0]: {"thicknessNm":100} is not allowed']],
    [['--cases', 'extra-key'], ['layers[0]: ']],
    [['--cases', 'bad-medium'], ['layers[1].n: "unobtainium" is not allowed']],
    [
      ['--cases', 'bad-index'],
      ['layers[0].n: 9 is not allowed', 'n is 9, above 4'],
    ],
    [['--cases', 'bad-thickness'], ['layers[0].thicknessNm: 20001 is not allowed; expected a number in [0, 20000] nm']],
  ])('refuses %j: %j', (args, words) => refused(args, ...words));
});

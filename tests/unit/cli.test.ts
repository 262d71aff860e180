/**
 * The command-line tool (src/cli). Expected values come from outside the code under test: the
 * golden film reflectance (docs/physics.md#golden-value), the normal-incidence Fresnel formula, the sRGB transfer
 * function as IEC 61966-2-1 defines it, and the definition of the CIE 1931 observer (equal-energy
 * white has x = y = z). The rows run the whole command in-process, files included (`colorCommand`);
 * two spawn the real CLI to prove the process glue: exit status, stdout, stderr.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { ParameterError, describeValue } from '../../src/input/validate.ts';
import { parseStrictNumber } from '../../src/cli/parseStrictNumber.ts';
import { runColorCommand } from '../../src/cli/runColorCommand.ts';
import { colorCommand } from '../../src/cli/colorCommand.ts';
import { jsonNestingDepth } from '../../src/cli/jsonNestingDepth.ts';
import { MAX_TABLE_ROWS, evenlySpaced } from '../../src/cli/tableValues.ts';
import { ABSURDLY_LONG, DEEPLY_NESTED, NOT_NUMBERS, notNames, outsideRange } from './fixtures/badValues.ts';
import { EQUAL_ENERGY_TOLERANCE, FLOAT_TOLERANCE, GOLDEN_TOL, WATER_INDEX_TOL } from '../tolerances.ts';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const FIXTURES = 'tests/unit/fixtures';
/** Each spawn starts tsx (~0.5 s); allow for a loaded machine. */
const SPAWN_TIMEOUT_MS = 30_000;

interface Spawned {
  readonly status: number | null;
  readonly stdout: string;
  readonly stderr: string;
}

/** The command in-process, as the process would run it (color.ts only prints this). */
function cli(...args: string[]): Spawned {
  const r = colorCommand(args);
  return { status: r.exitCode, stdout: r.stdout, stderr: r.stderr };
}

/** The real CLI in a process of its own. */
function spawned(...args: string[]): Spawned {
  const r = spawnSync('node_modules/.bin/tsx', ['src/cli/color.ts', ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

interface CaseOutput {
  id: string | number;
  illuminant: unknown;
  lightTint: unknown;
  normalization: string;
  xyz: number[];
  linearSrgb: number[];
  srgb8: number[];
  linearWideGamut: number[];
  displayP3_8: number[];
  reflectance: number[];
  nFilm: number[];
  thicknessNm?: number;
  angleDeg?: number;
  hex?: string;
}

function cliJson(...args: string[]): CaseOutput[] {
  const r = cli(...args);
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  return JSON.parse(r.stdout) as CaseOutput[];
}

/** Fresnel at normal incidence, the bare a|c interface: ((n_a − n_c)/(n_a + n_c))². */
const bareInterfaceR = (na: number, nc: number) => ((na - nc) / (na + nc)) ** 2;
/** IEC 61966-2-1: the 8-bit code of a linear value in [0, 1]. */
const srgb8Of = (v: number) => Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055));

describe('color CLI, dispersive films', () => {
  it(
    'reports n_b(λ) at each wavelength (water: the measured D and C lines in air × 1.00028) and R(λ) with that index',
    { timeout: SPAWN_TIMEOUT_MS },
    () => {
      const [water] = cliJson('--n-film', 'water', '--thickness', '400', '--wavelengths', '589.29,656.28');
      expect(water!.nFilm).toHaveLength(2);
      [1.33299, 1.33114].forEach((nAir, i) => expect(Math.abs(water!.nFilm[i]! - nAir * 1.00028)).toBeLessThan(WATER_INDEX_TOL));
      // R at one wavelength is the constant film's R with the index the film has there.
      const [constant] = cliJson('--n-film', String(water!.nFilm[0]), '--thickness', '400', '--wavelengths', '589.29');
      expect(Math.abs(water!.reflectance[0]! - constant!.reflectance[0]!)).toBeLessThan(FLOAT_TOLERANCE);
      expect(constant!.nFilm).toEqual([water!.nFilm[0]]);
    },
  );

  it(
    'takes a Cauchy film from a flag and from a cases file alike, and refuses one outside the index domain',
    { timeout: SPAWN_TIMEOUT_MS },
    () => {
      const [flag] = cliJson('--n-film', 'cauchy:1.45,6000', '--thickness', '700', '--angle', '30');
      const [file] = cliJson('--cases', 'tests/unit/fixtures/cli-dispersive-cases.json');
      expect(file!.xyz).toEqual(flag!.xyz);
      const bad = spawned('--n-film', 'cauchy:3.9,20000');
      expect(bad.status).toBe(2);
      expect(bad.stdout).toBe('');
      expect(bad.stderr).toMatch(/^color: --n-film: "cauchy:3.9,20000" is not allowed; .* \(here n at 380 nm is 4.0385, above 4\)\n$/);
    },
  );
});

describe('color CLI, one case from flags', () => {
  it('reproduces the golden reflectance R(555 nm) = 0.1215919 (n 1.5 in air, 250 nm, 0°)', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const out = cliJson('--n-film', '1.5', '--thickness', '250', '--angle', '0', '--wavelengths', '555');
    expect(out).toHaveLength(1);
    const [c] = out as [CaseOutput];
    expect(c.id).toBe(0);
    expect(c.normalization).toBe('white');
    expect(c.illuminant).toBe('D65');
    expect(c.reflectance).toHaveLength(1);
    expect(Math.abs((c.reflectance[0] as number) - 0.1215919)).toBeLessThan(GOLDEN_TOL);
  });

  it('a film of thickness 0 between equal media reflects nothing: black', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const [c] = cliJson('--thickness', '0', '--angle', '40', '--wavelengths', '400,700') as [CaseOutput];
    expect(c.xyz).toEqual([0, 0, 0]);
    expect(c.srgb8).toEqual([0, 0, 0]);
    expect(c.displayP3_8).toEqual([0, 0, 0]);
    expect(c.reflectance).toEqual([0, 0]);
  });

  const bareTitle = 'a bare interface reflects ((n_a − n_c)/(n_a + n_c))² at every λ, so Y = R and the colour is grey';
  it(bareTitle, { timeout: SPAWN_TIMEOUT_MS }, () => {
    const args = ['--thickness', '0', '--n-outside', '1', '--n-inside', '1.5', '--wavelengths', '300,400,555,700,830'];
    const [c] = cliJson(...args) as [CaseOutput];
    const r = bareInterfaceR(1, 1.5);
    for (const value of c.reflectance) expect(Math.abs(value - r)).toBeLessThan(FLOAT_TOLERANCE);
    expect(Math.abs((c.xyz[1] as number) - r)).toBeLessThan(FLOAT_TOLERANCE);
    // D65 maps to sRGB white within ~1 %, so each channel is the code of R, give or take one.
    for (const code of [...c.srgb8, ...c.displayP3_8]) expect(Math.abs(code - srgb8Of(r))).toBeLessThanOrEqual(1);
  });

  it('prints usage for --help', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const r = spawned('--help');
    expect(r.status).toBe(0);
    expect(r.stdout).toContain('Usage: npm run --silent color');
    expect(r.stderr).toBe('');
  });
});

describe('color CLI, cases file', () => {
  const out = () => cliJson('--cases', `${FIXTURES}/cli-cases.json`);

  it('answers every case, in input order, with defaults filled in and stated', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const cases = out();
    expect(cases.map((c) => c.id)).toEqual(['bare-glass', 1, 42, 's-head-on', 'p-head-on', 'paper-normalization']);
    const [bare, empty, paper, s, p, paperNorm] = cases as [CaseOutput, CaseOutput, CaseOutput, CaseOutput, CaseOutput, CaseOutput];
    // Bare glass under equal energy: R = 0.04 everywhere and X = Y = Z (CIE 1931's equal-energy white).
    expect(bare.illuminant).toBe('E');
    for (const value of bare.reflectance) expect(Math.abs(value - bareInterfaceR(1, 1.5))).toBeLessThan(FLOAT_TOLERANCE);
    for (const v of bare.xyz) expect(Math.abs(v / bareInterfaceR(1, 1.5) - 1)).toBeLessThan(EQUAL_ENERGY_TOLERANCE);
    // An empty object is the default case: a soap film in air, D65, white normalisation.
    expect(empty.illuminant).toBe('D65');
    expect(empty.normalization).toBe('white');
    expect(empty.reflectance).toEqual([]);
    // The paper's amplitude average vanishes at normal incidence (docs/physics.md#paper-mode-at-normal-incidence): a black film.
    expect(paper.reflectance).toEqual([0, 0]);
    expect(paper.xyz).toEqual([0, 0, 0]);
    // s and p are the same wave at normal incidence.
    expect(s.illuminant).toEqual({ daylightCct: 7500 });
    for (let i = 0; i < 3; i++) expect(Math.abs((s.xyz[i] as number) - (p.xyz[i] as number))).toBeLessThan(FLOAT_TOLERANCE);
    expect(paperNorm.normalization).toBe('paper');
    expect(paperNorm.illuminant).toBe('D65-table');
  });
});

describe('color CLI, tables', () => {
  const csvTitle = 'a CSV thickness table has (to − from)/step + 1 rows after its header, hex matching srgb8';
  it(csvTitle, { timeout: SPAWN_TIMEOUT_MS }, () => {
    const r = cli('--from', '0', '--to', '1500', '--step', '10', '--format', 'csv');
    expect(r.status).toBe(0);
    const lines = r.stdout.trimEnd().split('\n');
    expect(lines).toHaveLength((1500 - 0) / 10 + 1 + 1);
    const header = (lines[0] as string).split(',');
    const col = (name: string) => header.indexOf(name);
    for (const line of lines.slice(1)) {
      const cells = line.split(',');
      const rgb = ['srgb8R', 'srgb8G', 'srgb8B'].map((n) => Number(cells[col(n)]));
      expect(cells[col('hex')]).toBe(`#${rgb.map((v) => v.toString(16).padStart(2, '0')).join('')}`);
    }
    expect(lines.slice(1).map((l) => Number(l.split(',')[col('thicknessNm')]))).toEqual(Array.from({ length: 151 }, (_, i) => i * 10));
  });

  it('a JSON thickness table equals the cases output for the same films', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const table = cliJson(
      ...['--from', '100', '--to', '400', '--step', '150', '--angle', '20', '--n-film', '1.4'],
      ...['--illuminant', 'D93', '--wavelengths', '500'],
    );
    const cases = cliJson('--cases', `${FIXTURES}/cli-thickness-cases.json`);
    expect(table.map((row) => row.thicknessNm)).toEqual([100, 250, 400]);
    expect(table.map(({ thicknessNm: _t, angleDeg: _a, hex: _h, ...rest }) => rest)).toEqual(cases);
  });

  it('an angle table runs FROM:TO:STEP at the given thickness', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const rows = cliJson('--angles', '0:85:5', '--thickness', '300', '--gamut', 'preserve-hue');
    expect(rows.map((row) => row.angleDeg)).toEqual(Array.from({ length: 18 }, (_, i) => i * 5));
    expect(new Set(rows.map((row) => row.thicknessNm))).toEqual(new Set([300]));
    for (const row of rows) expect(row.hex).toMatch(/^#[0-9a-f]{6}$/);
  });
});

describe('color CLI, a tinted light', () => {
  it('--light-tint 1,1,1 is the untinted light; the output names the tint', () => {
    const plain = cliJson('--illuminant', 'FL2', '--thickness', '450');
    const white = cliJson('--illuminant', 'FL2', '--thickness', '450', '--light-tint', '1,1,1');
    expect(white).toEqual(plain);
    expect(plain[0]!.lightTint).toEqual([1, 1, 1]);
  });

  it("a cases file's tints add up as light does: (1, 0.5, 0.2) is the sum of its three primaries' films", () => {
    const tints = [
      [1, 0, 0],
      [0, 0.5, 0],
      [0, 0, 0.2],
      [1, 0.5, 0.2],
    ];
    const text = JSON.stringify(tints.map((lightTint, id) => ({ id, lightTint, illuminant: 'D65', thicknessNm: 700, angleDeg: 30 })));
    const r = runColorCommand(['--cases', 'tints.json'], () => text);
    expect(r.exitCode).toBe(0);
    const rows = JSON.parse(r.stdout) as CaseOutput[];
    expect(rows.map((row) => row.lightTint)).toEqual(tints);
    for (let k = 0; k < 3; k++) {
      const sum = rows[0]!.xyz[k]! + rows[1]!.xyz[k]! + rows[2]!.xyz[k]!;
      expect(Math.abs(sum - rows[3]!.xyz[k]!)).toBeLessThan(FLOAT_TOLERANCE);
    }
  });
});

describe('color CLI, gamut mapping', () => {
  const title = 'preserve-hue changes the 8-bit codes of an out-of-gamut colour, not its linear values';
  it(title, { timeout: SPAWN_TIMEOUT_MS }, () => {
    // 500 nm at 30°: a saturated cyan with a negative linear red (outside sRGB).
    const flags = ['--thickness', '500', '--angle', '30'];
    const [clip] = cliJson(...flags) as [CaseOutput];
    const [hue] = cliJson(...flags, '--gamut', 'preserve-hue') as [CaseOutput];
    expect(Math.min(...clip.linearSrgb)).toBeLessThan(0);
    expect(hue.linearSrgb).toEqual(clip.linearSrgb);
    expect(hue.srgb8).not.toEqual(clip.srgb8);
    for (const code of [...hue.srgb8, ...clip.srgb8]) expect(code >= 0 && code <= 255).toBe(true);
  });
});

describe('color CLI, bad input through the process', () => {
  const nested = join(mkdtempSync(join(tmpdir(), 'color-cli-')), 'nested.json');
  writeFileSync(nested, DEEPLY_NESTED);
  const rows: [string[], string][] = [
    [['--cases', nested], '--cases: '],
    [['--thickness', '12abc'], '--thickness'],
    [['--bogus', '1'], '--bogus'],
    [['--cases', `${FIXTURES}/cli-cases-malformed.json`], '--cases'],
    [['--cases', `${FIXTURES}/no-such-file.json`], '--cases'],
  ];
  it.each(rows)('%j → exit 2, one stderr line naming %s, empty stdout', { timeout: SPAWN_TIMEOUT_MS }, (args, name) => {
    const r = cli(...args);
    expect(r.status).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.endsWith('\n')).toBe(true);
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(name);
  });
});

/** Files the in-process runs can read; anything else "does not exist". */
const FILES: Record<string, string> = {
  'not-json': '[{ "id": 1, }]',
  object: '{ "thicknessNm": 500 }',
  'not-an-object': '[{ "id": "ok" }, 7]',
  'unknown-field': '[{ "id": "typo", "thickness": 500 }]',
  'string-number': '[{ "id": "s", "thicknessNm": "500" }]',
  'null-angle': '[{ "id": "n", "angleDeg": null }]',
  infinite: '[{ "id": "inf", "thicknessNm": 1e999 }]',
  'thick-second': '[{ "id": "fine" }, { "id": "too-thick", "thicknessNm": 20001 }]',
  'bad-index': '[{ "id": "idx", "nFilm": 4.5 }]',
  'bad-cct': '[{ "id": "cct", "illuminant": { "daylightCct": 3000 } }]',
  'extra-cct-key': '[{ "id": "cct2", "illuminant": { "daylightCct": 7500, "x": 1 } }]',
  'bad-illuminant': '[{ "id": "ill", "illuminant": "A" }]',
  'bad-wavelength': '[{ "id": "wl", "wavelengthsNm": [500, 900] }]',
  'wavelengths-string': '[{ "id": "wls", "wavelengthsNm": "500" }]',
  'bad-polarization': '[{ "id": "pol", "polarization": "circular" }]',
  'bad-normalization': '[{ "id": "norm", "normalization": "max" }]',
  'long-id': `[{ "id": "${'x'.repeat(5000)}" }]`,
  'object-id': '[{ "id": { "a": 1 } }]',
  'deeply-nested': DEEPLY_NESTED,
  'nested-in-case': `[{ "id": "deep", "wavelengthsNm": ${'['.repeat(17)}${']'.repeat(17)} }]`,
};
const readFake = (path: string): string => {
  const text = FILES[path];
  if (text === undefined) throw new ParameterError('--cases', `--cases: ${path} cannot be read (ENOENT)`);
  return text;
};

describe('color CLI, bad input (in-process: the whole command but the process)', () => {
  const huge = '9'.repeat(100_000);
  const rows: [string[], string, string?][] = [
    [['--thickness', ''], '--thickness'],
    [['--thickness'], '--thickness'],
    [['--thickness', 'NaN'], '--thickness'],
    [['--thickness', 'Infinity'], '--thickness'],
    [['--thickness', '1e999'], '--thickness'],
    [['--thickness', ' 500'], '--thickness'],
    [['--thickness', '0x1f'], '--thickness'],
    [['--thickness', '-1'], '--thickness'],
    [['--thickness', '20000.5'], '--thickness'],
    [['--thickness', huge], '--thickness'],
    [['--angle', '-0.1'], '--angle'],
    [['--angle', '90.01'], '--angle'],
    [['--n-film', '0.99'], '--n-film'],
    [['--n-outside', '4.01'], '--n-outside'],
    [['--n-inside', 'one'], '--n-inside'],
    [['--illuminant', '3999'], '--illuminant'],
    [['--illuminant', '25001'], '--illuminant'],
    [['--illuminant', 'A'], '--illuminant'],
    [['--polarization', 'circular'], '--polarization'],
    [['--normalization', 'max'], '--normalization'],
    [['--gamut', 'squash'], '--gamut'],
    [['--format', 'xml'], '--format'],
    [['--format', 'csv'], '--format'],
    [['--wavelengths', '299.9'], '--wavelengths'],
    [['--wavelengths', '400,,500'], '--wavelengths'],
    [['--wavelengths', '400,830.5'], '--wavelengths'],
    [['--thickness', '1', '--thickness', '2'], '--thickness'],
    [['stray'], 'argument'],
    [['--unknown-flag'], '--unknown-flag'],
    [['--from', '0', '--to', '100'], '--step'],
    [['--from', '0', '--to', '20000', '--step', '0.1'], '--step'],
    [['--from', '0', '--to', '100', '--step', '0'], '--step'],
    [['--from', '100', '--to', '0', '--step', '10'], '--to'],
    [['--from', '0', '--to', '20001', '--step', '10'], '--to'],
    [['--from', '0', '--to', '100', '--step', '10', '--thickness', '5'], '--thickness'],
    [['--angles', '0:85'], '--angles'],
    [['--angles', '0:95:5'], '--angles'],
    [['--angles', '0:85:5', '--angle', '3'], '--angle'],
    [['--cases', 'object', '--thickness', '5'], '--thickness'],
    [['--cases', ''], '--cases'],
    [['--cases', 'missing'], '--cases'],
    [['--cases', 'not-json'], '--cases'],
    [['--cases', 'object'], '--cases'],
    [['--cases', 'not-an-object'], 'case', 'index 1'],
    [['--cases', 'unknown-field'], 'thickness', '"typo"'],
    [['--cases', 'string-number'], 'thicknessNm', '"s"'],
    [['--cases', 'null-angle'], 'angleDeg', '"n"'],
    [['--cases', 'infinite'], 'thicknessNm', '"inf"'],
    [['--cases', 'thick-second'], 'thicknessNm', '"too-thick"'],
    [['--cases', 'bad-index'], 'nFilm', '"idx"'],
    [['--cases', 'bad-cct'], 'illuminant', '"cct"'],
    [['--cases', 'extra-cct-key'], 'illuminant', '"cct2"'],
    [['--cases', 'bad-illuminant'], 'illuminant', '"ill"'],
    [['--cases', 'bad-wavelength'], 'wavelengthsNm[1]', '"wl"'],
    [['--cases', 'wavelengths-string'], 'wavelengthsNm', '"wls"'],
    [['--cases', 'bad-polarization'], 'polarization', '"pol"'],
    [['--cases', 'bad-normalization'], 'normalization', '"norm"'],
    [['--cases', 'long-id'], 'id', 'index 0'],
    [['--cases', 'object-id'], 'id', 'index 0'],
    [['--cases', 'deeply-nested'], '--cases', 'malformed'],
    [['--cases', 'nested-in-case'], '--cases', 'malformed'],
  ];
  it.each(rows)('%j → exit 2, one line naming %s', (args, name, caseLabel) => {
    const r = runColorCommand(args, readFake);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(name);
    if (caseLabel) expect(r.stderr).toContain(caseLabel);
    // Echoed values are cut short: no 100 000-digit lines.
    expect(r.stderr.length).toBeLessThan(400);
  });

  it('states the allowed range', () => {
    expect(runColorCommand(['--angle', '91'], readFake).stderr).toContain('[0, 90]');
    expect(runColorCommand(['--illuminant', '3000'], readFake).stderr).toContain('[4000, 25000]');
    expect(runColorCommand(['--cases', 'thick-second'], readFake).stderr).toContain('[0, 20000] nm');
  });

  it('says how deeply a malformed cases file nests (100 000 brackets, and 17 + 1 inside a case)', () => {
    expect(runColorCommand(['--cases', 'deeply-nested'], readFake).stderr).toContain('nest 100000 deep');
    expect(runColorCommand(['--cases', 'nested-in-case'], readFake).stderr).toContain('nest 19 deep');
  });

  it('brackets inside strings do not count as nesting', () => {
    const text = `[{ "id": "${'['.repeat(90)}\\"${'{'.repeat(90)}" }]`;
    const r = runColorCommand(['--cases', 'c.json'], () => text);
    expect(r.stderr).toBe('');
    expect(r.exitCode).toBe(0);
  });
});

/**
 * The table of bad values for every numeric and named flag and every cases-file field.
 * Ranges and names are written out as the README documents them, not read from src/cli.
 */
describe('color CLI, the table of bad values', () => {
  /** A message repeats a bad value's start; 20 characters is inside every cut. */
  const ECHO_CHARS = 20;
  const NUMERIC_FLAGS: Record<string, [number, number]> = {
    '--thickness': [0, 20000],
    '--angle': [0, 90],
    '--n-outside': [1, 4],
    '--n-film': [1, 4],
    '--n-inside': [1, 4],
    '--wavelengths': [300, 830],
  };
  const NAMED_FLAGS: Record<string, readonly string[]> = {
    '--polarization': ['unpolarized', 'paper', 's', 'p'],
    '--normalization': ['white', 'paper'],
    '--gamut': ['clip', 'preserve-hue'],
  };
  /** The message quotes the value it refuses: the whole text, or the bad number inside a list or range. */
  type Row = [args: string[], parameter: string, echoed: string, range: string];
  const flagRows: Row[] = [
    ...Object.entries(NUMERIC_FLAGS).flatMap(([flag, [min, max]]) =>
      [...NOT_NUMBERS, ...outsideRange(min, max)].map((v): Row =>
        // A wavelength list's errors name the element ("1,5" is the list [1, 5]; 1 is refused).
        flag === '--wavelengths'
          ? [[flag, v], `${flag}[0]`, v.split(',')[0]!, `[${min}, ${max}]`]
          : [[flag, v], flag, v, `[${min}, ${max}]`],
      ),
    ),
    [['--wavelengths', '500,1e999'], '--wavelengths[1]', '1e999', '[300, 830]'],
    [['--wavelengths', '500,900'], '--wavelengths[1]', '900', '[300, 830]'],
    ...Object.entries(NAMED_FLAGS).flatMap(([flag, allowed]) =>
      notNames(allowed).map((v): Row => [[flag, v], flag, v, allowed.join(', ')]),
    ),
    ...[...NOT_NUMBERS, ...outsideRange(4000, 25000), ...notNames(['D65', 'E']), 'FL13', 'line:379.9', 'line:780.1', 'line:'].map(
      (v): Row => [
        ['--illuminant', v],
        '--illuminant',
        v,
        'FL1–FL12, LED-B1–LED-B5, LED-BH1, LED-RGB1, LED-V1, LED-V2, Na, line:NM with NM in [380, 780] nm, or a daylight CCT in [4000, 25000] K',
      ],
    ),
    ...['', '0.5', '0.5,0.5', '0.5,0.5,0.5,0.5', '1.01,0.5,0.5', '0.5,-0.01,0.5', '0.5,0.5,NaN', '0.5,,0.5', 'red'].map((v): Row => [
      ['--light-tint', v],
      '--light-tint',
      v,
      'three numbers R,G,B, each in [0, 1]',
    ]),
    ...notNames(['json', 'csv']).map((v): Row => [['--angles', '0:10:5', '--format', v], '--format', v, 'json, csv']),
    ...(['--from', '--to'] as const).flatMap((flag) =>
      [...NOT_NUMBERS, ...outsideRange(0, 20000)].map((v): Row => {
        const args = { '--from': '0', '--to': '100', '--step': '10', [flag]: v };
        return [Object.entries(args).flat(), flag, v, '[0, 20000]'];
      }),
    ),
    ...[...NOT_NUMBERS, '0', '-10'].map((v): Row => [['--from', '0', '--to', '100', '--step', v], '--step', v, '> 0']),
    ...[...NOT_NUMBERS, '0:10', '0:10:5:1'].map((v): Row => [['--angles', v], '--angles', v, '[0, 90]']),
    [['--angles', '0:95:5'], '--angles', '95', '[0, 90]'],
    [['--angles', '-5:10:5'], '--angles', '-5', '[0, 90]'],
  ];

  it.each(flagRows)('%j → exit 2, one line naming %s, the value %j and %s', (args, parameter, echoed, range) => {
    const r = runColorCommand(args, readFake);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(`${parameter}: `);
    expect(r.stderr).toContain(echoed === '' ? '""' : echoed.slice(0, ECHO_CHARS));
    expect(r.stderr).toContain(range);
    expect(r.stderr.length).toBeLessThan(400);
  });

  /** JSON values that are not a number in range (1e999 parses to Infinity). */
  const badJsonNumbers = (min: number, max: number): string[] => [
    '"abc"',
    '""',
    '"500"',
    'null',
    'true',
    '[]',
    '{}',
    `"${ABSURDLY_LONG}"`,
    ...outsideRange(min, max),
  ];
  const FIELDS: Record<string, [number, number]> = {
    thicknessNm: [0, 20000],
    angleDeg: [0, 90],
    nOutside: [1, 4],
    nFilm: [1, 4],
    nInside: [1, 4],
  };
  /** [field, JSON value, the field as the message names it, what it echoes, the range]; JSON's 1e999 is Infinity. */
  type CaseRow = [field: string, json: string, named: string, echoed: string, range: string];
  const row = (field: string, json: string, range: string): CaseRow => [field, json, field, json, range];
  const caseRows: CaseRow[] = [
    ...Object.entries(FIELDS).flatMap(([field, [min, max]]) => [
      ...badJsonNumbers(min, max).map((v) => row(field, v, `[${min}, ${max}]`)),
      [field, '1e999', field, 'Infinity', `[${min}, ${max}]`] as CaseRow,
      [field, '-1e999', field, '-Infinity', `[${min}, ${max}]`] as CaseRow,
    ]),
    ...[...badJsonNumbers(4000, 25000), '"bogus"', '"d65"', '{ "daylightCct": "7500" }', '{ "daylightCct": 3000 }'].map((v) =>
      row('illuminant', v, '[4000, 25000] K'),
    ),
    ['illuminant', '{ "daylightCct": 1e999 }', 'illuminant', '{"daylightCct":null}', '[4000, 25000] K'],
    ...[
      '"1,0.5,0.2"',
      '[1, 0.5]',
      '[1, 0.5, 0.2, 0]',
      '[1.5, 0.5, 0.2]',
      '[1, -0.5, 0.2]',
      '[1, "0.5", 0.2]',
      '[1, null, 0.2]',
      'null',
      '1',
    ].map((v) => row('lightTint', v, 'three numbers R,G,B, each in [0, 1]')),
    ...['"bogus"', '""', '"S"', 'null', '1', `"${ABSURDLY_LONG}"`].map((v) => row('polarization', v, 'unpolarized, paper, s, p')),
    ...['"bogus"', '""', '"White"', 'null', '1'].map((v) => row('normalization', v, 'white, paper')),
    ...['"500"', '500', '{}'].map((v) => row('wavelengthsNm', v, '[300, 830]')),
    ['wavelengthsNm', '[500, null]', 'wavelengthsNm[1]', 'null', '[300, 830]'],
    ['wavelengthsNm', '[500, 1e999]', 'wavelengthsNm[1]', 'Infinity', '[300, 830]'],
    ['wavelengthsNm', '[299]', 'wavelengthsNm[0]', '299', '[300, 830]'],
    ['wavelengthsNm', '[831]', 'wavelengthsNm[0]', '831', '[300, 830]'],
    ['wavelengthsNm', '["500"]', 'wavelengthsNm[0]', '"500"', '[300, 830]'],
  ];

  it.each(caseRows)('a case with %s: %s → exit 2, one line naming %s, the case, %s and %s', (field, json, named, echoed, range) => {
    const text = `[{ "id": "ok" }, { "id": "bad", "${field}": ${json} }]`;
    const r = runColorCommand(['--cases', 'cases.json'], () => text);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(`${named}: `);
    expect(r.stderr).toContain('"bad"');
    expect(r.stderr).toContain(echoed.slice(0, ECHO_CHARS).replace(/ /g, ''));
    expect(r.stderr).toContain(range);
    expect(r.stderr.length).toBeLessThan(400);
  });
});

describe('strict parsing helpers', () => {
  it('parseStrictNumber reads decimal numbers only', () => {
    for (const [text, value] of [
      ['500', 500],
      ['1e3', 1000],
      ['-0.5', -0.5],
      ['.5', 0.5],
      ['+7', 7],
      ['5.', 5],
    ] as const) {
      expect(parseStrictNumber('x', text, 'a number')).toBe(value);
    }
    for (const text of ['', ' 5', '5 ', '12abc', '0x10', '0b1', 'Infinity', '-Infinity', 'NaN', '1e999', '1,5', '--5']) {
      expect(() => parseStrictNumber('x', text, 'a number'), text).toThrow(ParameterError);
    }
  });

  it('evenlySpaced includes both ends and rounds away binary noise', () => {
    const names = { from: 'f', to: 't', step: 's' };
    expect(evenlySpaced(0, 1, 0.1, names)).toEqual([0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]);
    expect(evenlySpaced(0, 95, 10, names)).toHaveLength(10);
    expect(evenlySpaced(7, 7, 1, names)).toEqual([7]);
    expect(evenlySpaced(0, MAX_TABLE_ROWS - 1, 1, names)).toHaveLength(MAX_TABLE_ROWS);
    expect(() => evenlySpaced(0, MAX_TABLE_ROWS, 1, names)).toThrow(ParameterError);
  });

  it('jsonNestingDepth counts open brackets, not those in strings', () => {
    expect(jsonNestingDepth('')).toBe(0);
    expect(jsonNestingDepth('[]')).toBe(1);
    expect(jsonNestingDepth('[{}, [[]], {"a": {"b": []}}]')).toBe(4);
    expect(jsonNestingDepth('["[[[", "\\"[{", {"k": "}}]]"}]')).toBe(2);
    expect(jsonNestingDepth(DEEPLY_NESTED)).toBe(100_000);
  });

  it('describeValue keeps a message to one short line', () => {
    expect(describeValue('a\nb')).toBe('"a\\nb"');
    expect(describeValue('x'.repeat(1000))).toMatch(/… \(1000 characters\)$/);
    expect(describeValue(undefined)).toBe('no value');
  });
});

/**
 * The film command (src/cli/film.ts). Expected values come from outside the code under test: the
 * specified output fields and profile angles, conservation of volume and surfactant without
 * evaporation, the mean lost to evaporation (E·t), and the option ranges of the flow parameter
 * table. Most rows run the command in-process (`runFilmCommand`); one spawns the real CLI to prove
 * the process glue: exit status, stderr, empty stdout.
 */
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { FILM_SECONDS_DOMAIN, PARAMETER_FLAGS, runFilmCommand } from '../../src/cli/runFilmCommand.ts';
import { NOT_NUMBERS, outsideRange } from './fixtures/badValues.ts';
import { CONSERVATION_REL_TOL, ROUNDING_TOL } from '../tolerances.ts';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** Each spawn starts tsx (~0.5 s); allow for a loaded machine. */
const SPAWN_TIMEOUT_MS = 30_000;

interface FilmOutput {
  seconds: number;
  steps: number;
  thetaDeg: number[];
  thicknessNm: number[];
  minNm: number;
  maxNm: number;
  volumeRelativeChange: number;
  surfactantRelativeChange: number;
  ruptured: boolean;
}

const runJson = (...args: string[]): FilmOutput => {
  const r = runFilmCommand(args);
  expect(r.stderr).toBe('');
  expect(r.exitCode).toBe(0);
  return JSON.parse(r.stdout) as FilmOutput;
};

describe('film command', () => {
  it('prints the specified fields: the profile at θ = 0, 5, …, 180°, the extremes, the conserved totals', () => {
    const out = runJson('--grid', '6', '--seed', '3', '--seconds', '0.5', '--json');
    expect(Object.keys(out).sort()).toEqual(
      [
        'maxNm',
        'minNm',
        'ruptured',
        'seconds',
        'steps',
        'surfactantRelativeChange',
        'thetaDeg',
        'thicknessNm',
        'volumeRelativeChange',
      ].sort(),
    );
    expect(out.thetaDeg).toEqual(Array.from({ length: 37 }, (_, k) => 5 * k));
    expect(out.thicknessNm).toHaveLength(37);
    expect(out.steps).toBeGreaterThan(0);
    // Whole steps: the last one that fits, within one step of the time asked.
    expect(out.seconds).toBeLessThanOrEqual(0.5);
    expect(out.seconds).toBeGreaterThan(0.5 - out.seconds / out.steps);
    expect(out.minNm).toBeLessThan(Math.min(...out.thicknessNm) + 1e-9);
    expect(out.maxNm).toBeGreaterThan(Math.max(...out.thicknessNm) - 1e-9);
    // Gravity drains the top into the bottom.
    expect(out.thicknessNm[36]!).toBeGreaterThan(out.thicknessNm[0]!);
    expect(Math.abs(out.volumeRelativeChange)).toBeLessThan(CONSERVATION_REL_TOL);
    expect(Math.abs(out.surfactantRelativeChange)).toBeLessThan(CONSERVATION_REL_TOL);
    expect(out.ruptured).toBe(false);
  });
  it('passes the options on: evaporation at 20 nm/s for 1 s takes 20 nm off a 300 nm film', () => {
    const out = runJson('--grid', '6', '--thickness', '300', '--evaporation', '20', '--radius', '20', '--seconds', '1');
    expect(Math.abs(out.volumeRelativeChange - -(20 * out.seconds) / 300)).toBeLessThan(1e-9);
    expect(Math.abs(out.surfactantRelativeChange)).toBeLessThan(ROUNDING_TOL);
  });
  it('reports a film that bursts', () => {
    const out = runJson('--grid', '4', '--thickness', '30', '--rupture-thickness', '29', '--evaporation', '100', '--seconds', '0.1');
    expect(out.ruptured).toBe(true);
  });
  it('prints usage for --help: the flow parameters spelt as the URL names them, in kebab case, and the two of its own', () => {
    const r = runFilmCommand(['--help']);
    expect(r.exitCode).toBe(0);
    const flags = [
      'radius',
      'thickness',
      'surfactant',
      'evaporation',
      'wind',
      'wind-turn',
      'seed',
      'rupture-thickness',
      'rim-speed-factor',
      'grid',
    ];
    expect(PARAMETER_FLAGS.map((p) => p.flag)).toEqual(flags);
    for (const flag of [...flags, 'seconds', 'json', 'progress']) expect(r.stdout).toContain(`--${flag} `);
    // The label is the schema's, written once (the catalogue's English).
    expect(r.stdout).toContain('  --radius              bubble radius (mm): a number in [10, 100] mm (40)\n');
  });
  it('reports film seconds done of the total and the time left on stderr when asked (--progress), and only then off a terminal', () => {
    const lines: string[] = [];
    const stream = { isTTY: false, write: (text: string) => lines.push(text) };
    const quiet = runFilmCommand(['--grid', '4', '--seconds', '0.2'], stream);
    expect(quiet.exitCode).toBe(0);
    expect(lines).toEqual([]);
    const asked = runFilmCommand(['--grid', '4', '--seconds', '0.2', '--progress'], stream);
    expect(asked.stdout).toBe(quiet.stdout);
    expect(lines[0]).toBe('film: film seconds 0.00/0.20 (0%)\n');
    expect(lines.at(-1)).toMatch(/^film: film seconds 0\.20\/0\.20 \(100%\), done in \d+:\d\d\n$/);
  });
  it('redraws one line on a terminal', () => {
    const written: string[] = [];
    runFilmCommand(['--grid', '4', '--seconds', '0.1'], { isTTY: true, write: (text: string) => written.push(text) });
    expect(written.every((text) => text.startsWith('\r'))).toBe(true);
    // Each redraw ends by clearing the rest of the line (ESC [K); the last ends the line.
    const last = written.at(-1)!;
    expect(last).toMatch(/^\rfilm: film seconds 0\.10\/0\.10 \(100%\), done in \d+:\d\d/);
    expect(last.endsWith('\u001b[K\n')).toBe(true);
  });
});

describe('film command, bad input', () => {
  const refused = (args: string[], flag: string) => {
    const r = runFilmCommand(args);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.startsWith(`film: ${flag}`)).toBe(true);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
  };
  for (const { flag: name, row } of PARAMETER_FLAGS) {
    const flag = `--${name}`;
    it(`${flag}: not a number or outside [${row.domain.min}, ${row.domain.max}]`, () => {
      for (const text of [...NOT_NUMBERS, ...outsideRange(row.domain.min, row.domain.max)]) refused([flag, text, '--seconds', '1'], flag);
      if (row.integer) refused([flag, String(row.domain.min + 0.5), '--seconds', '1'], flag);
    });
  }
  it('--seconds: missing, not a number or outside its range', () => {
    refused(['--grid', '4'], '--seconds');
    for (const text of [...NOT_NUMBERS, ...outsideRange(FILM_SECONDS_DOMAIN.min, FILM_SECONDS_DOMAIN.max)])
      refused(['--seconds', text], '--seconds');
  });
  it('unknown flags, repeated flags, positional arguments, a value for --json', () => {
    refused(['--seconds', '1', '--bogus', '3'], '"--bogus"');
    refused(['--seconds', '1', '--seconds', '2'], '--seconds');
    refused(['--seconds', '1', 'extra'], 'argument');
    refused(['--seconds', '1', '--json=yes'], '--json');
  });
  it.each([
    ['--thickness-nm', '--thickness'],
    ['--radius-mm', '--radius'],
    ['--rupture-nm', '--rupture-thickness'],
    ['--windTurn', '--wind-turn'],
  ])('refuses the spelling %s, naming %s', (old, flag) => {
    const r = runFilmCommand([old, '1', '--seconds', '1']);
    expect(r.exitCode).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe(`film: ${old}: unknown flag; it is spelt ${flag}\n`);
  });
  it('the real process: exit 2, one line on stderr, nothing on stdout', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const r = spawnSync('node_modules/.bin/tsx', ['src/cli/film.ts', '--wind', '3', '--seconds', '1', '--json'], {
      cwd: ROOT,
      encoding: 'utf8',
    });
    expect(r.status).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe('film: --wind: 3 is not allowed; expected a number in [0, 2] m/s\n');
  });
});

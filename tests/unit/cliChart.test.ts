/**
 * Charts of the colour tool (`--format png|svg`). The reference is the tool's own JSON table of
 * the same films (the table the chart draws): every cell must carry that row's srgb8 exactly.
 * The PNG is decoded with pngjs and the SVG parsed with @xmldom/xmldom, both independent of the
 * code that wrote them.
 */
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { DOMParser } from '@xmldom/xmldom';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { runColorCommand } from '../../src/cli/runColorCommand.ts';
import { colorCommand } from '../../src/cli/colorCommand.ts';
import { ABSURDLY_LONG, NOT_NUMBERS } from './fixtures/badValues.ts';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** Each spawn starts tsx (~0.5 s); allow for a loaded machine. */
const SPAWN_TIMEOUT_MS = 60_000;

/** The command in-process, files written as the process writes them (color.ts only prints this). */
function cli(...args: string[]) {
  const r = colorCommand(args);
  return { status: r.exitCode, stdout: r.stdout, stderr: r.stderr };
}

/** The real CLI in a process of its own. */
function spawned(...args: string[]) {
  const r = spawnSync('node_modules/.bin/tsx', ['src/cli/color.ts', ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}
interface Row {
  thicknessNm: number;
  angleDeg: number;
  srgb8: [number, number, number];
  hex: string;
}
function table(...args: string[]): Row[] {
  const r = cli(...args);
  expect(r.stderr).toBe('');
  return JSON.parse(r.stdout) as Row[];
}
const newDir = () => mkdtempSync(join(tmpdir(), 'color-chart-'));
const pixel = (png: PNG, x: number, y: number) => {
  const at = (y * png.width + x) * 4;
  return [png.data[at], png.data[at + 1], png.data[at + 2], png.data[at + 3]];
};

describe('color chart, PNG', () => {
  it('column i is row i of the table in srgb8 exactly, on every row 0..height−1', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const out = join(newDir(), 'scale.png');
    const range = ['--from', '0', '--to', '1500', '--step', '2', '--n-film', '1.4'];
    const r = cli(...range, '--format', 'png', '--out', out, '--height', '37');
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const printed = JSON.parse(r.stdout) as { out: string; width: number; height: number };
    expect(printed.out).toBe(out);
    expect(printed.width).toBeGreaterThan(0);
    expect(printed.height).toBeGreaterThan(0);
    const rows = table(...range);
    expect(rows).toHaveLength(751);
    const png = PNG.sync.read(readFileSync(out));
    expect(png.width).toBeGreaterThanOrEqual(rows.length);
    expect(png.height).toBeGreaterThan(37);
    rows.forEach((row, i) => {
      for (let y = 0; y < 37; y++) expect(pixel(png, i, y), `column ${i}, row ${y}`).toEqual([...row.srgb8, 255]);
    });
    // The margin below the strip is not the strip: its first row is white paper or black ink.
    const below = new Set(rows.map((_, i) => pixel(png, i, 37).join()));
    for (const p of below) expect(['255,255,255,255', '0,0,0,255']).toContain(p);
  });

  it('a 2-D chart: thickness along x, angle down y, each cell one table entry', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const out = join(newDir(), 'grid.png');
    const range = ['--from', '0', '--to', '1000', '--step', '50'];
    const angles = [0, 40, 80];
    expect(cli(...range, '--angles', '0:80:40', '--format', 'png', '--out', out).status).toBe(0);
    const png = PNG.sync.read(readFileSync(out));
    // The usage says each cell is 1 × 4 px.
    const cellHeight = 4;
    angles.forEach((angle, j) => {
      const rows = table(...range, '--angle', String(angle));
      rows.forEach((row, i) => {
        for (let dy = 0; dy < cellHeight; dy++)
          expect(pixel(png, i, j * cellHeight + dy), `${row.thicknessNm} nm, ${angle}°`).toEqual([...row.srgb8, 255]);
      });
    });
  });
});

describe('color chart, SVG', () => {
  it('parses and holds one rect per row of the table, in order, in its hex colour', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const out = join(newDir(), 'scale.svg');
    const range = ['--from', '100', '--to', '900', '--step', '4', '--angle', '30'];
    expect(cli(...range, '--format', 'svg', '--out', out).status).toBe(0);
    const errors: string[] = [];
    const doc = new DOMParser({ onError: (level, message) => errors.push(`${level}: ${message}`) }).parseFromString(
      readFileSync(out, 'utf8'),
      'image/svg+xml',
    );
    expect(errors).toEqual([]);
    const rows = table(...range);
    const rects = Array.from(doc.getElementsByTagName('rect'));
    expect(rects).toHaveLength(rows.length);
    rects.forEach((rect, i) => {
      expect(rect.getAttribute('fill')).toBe(rows[i]?.hex);
      expect(Number(rect.getAttribute('x'))).toBe(i);
    });
    const labels = Array.from(doc.getElementsByTagName('text')).map((t) => t.textContent);
    expect(labels).toContain('200');
  });
});

describe('color chart, bad input', () => {
  const range = ['--from', '0', '--to', '1500', '--step', '2'];
  const rows: [string[], string, string][] = [
    [[...range, '--format', 'png'], '--out', 'path'],
    [[...range, '--format', 'svg', '--out', ''], '--out', 'path'],
    [['--format', 'png', '--out', 'x.png'], '--format', 'table'],
    [[...range, '--out', 'x.png'], '--out', 'png and svg'],
    [[...range, '--height', '60'], '--height', 'png and svg'],
    ...[...NOT_NUMBERS, '0', '1001', '2.5', '-1'].map((v): [string[], string, string] => [
      [...range, '--format', 'png', '--out', 'x.png', '--height', v],
      '--height',
      '[1, 1000]',
    ]),
    [[...range, '--angles', '0:85:1', '--height', '10', '--format', 'png', '--out', 'x.png'], '--height', '1 × 4 px'],
    [[...range, '--angles', '0:85:1', '--angle', '5', '--format', 'png', '--out', 'x.png'], '--angle', '--angles'],
    [['--from', '0', '--to', '20000', '--step', '0.5', '--format', 'png', '--out', 'x.png'], '--step', '20000'],
    [['--from', '0', '--to', '19000', '--step', '1', '--height', '1000', '--format', 'png', '--out', 'x.png'], '--height', '16777216'],
    [['--from', '0', '--to', '15000', '--step', '1', '--angles', '0:90:0.1', '--format', 'svg', '--out', 'x.svg'], '--angles', '16777216'],
    [[...range, '--format', 'png', '--out', 'x.png', '--thickness', '5'], '--thickness', 'varies'],
    [[...range, '--format', 'png', '--out', 'x.png', '--n-film', ABSURDLY_LONG], '--n-film', '[1, 4]'],
  ];
  it.each(rows)('%j → exit 2, one line naming %s and %s, no file', (args, flag, expected) => {
    const r = runColorCommand(args, () => '');
    expect(r.exitCode).toBe(2);
    expect(r.file).toBeUndefined();
    expect(r.stdout).toBe('');
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(`${flag}: `);
    expect(r.stderr).toContain(expected);
    expect(r.stderr.length).toBeLessThan(400);
  });

  it('through the process: exit 2 and nothing written, also when the folder is missing', { timeout: SPAWN_TIMEOUT_MS }, () => {
    const dir = newDir();
    const bad = spawned(...range, '--format', 'png', '--out', join(dir, 'x.png'), '--height', '0');
    expect(bad.status).toBe(2);
    expect(bad.stdout).toBe('');
    expect(bad.stderr).toContain('--height: ');
    const missing = spawned(...range, '--format', 'png', '--out', join(dir, 'no-such-folder', 'x.png'));
    expect(missing.status).toBe(2);
    expect(missing.stdout).toBe('');
    expect(missing.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(missing.stderr).toContain('--out: ');
    expect(readdirSync(dir)).toEqual([]);
    expect(existsSync(join(dir, 'no-such-folder'))).toBe(false);
  });
});

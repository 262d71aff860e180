/**
 * The benchmark's command line is read before anything starts: a bad row or flag exits 2 naming
 * it and listing what is allowed (the spawn checks that no server or browser comes first).
 */
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { BENCH_FLAGS, parseBenchArgs } from '../../../scripts/bench/benchArgs.ts';

const ROOT = fileURLToPath(new URL('../../..', import.meta.url));
/** tsx starts in ~0.5 s; allow for a loaded machine. */
const SPAWN_TIMEOUT_MS = 60_000;
const ROWS = ['plain textured sphere (the floor)', 'exact, 45 bins', 'exact, 90 bins', 'table (default)'];

describe('bench command line', () => {
  it('takes --smoke and a list of texts each picking a row', () => {
    expect(parseBenchArgs([], ROWS)).toEqual({ args: { help: false, smoke: false, only: null, port: null } });
    expect(parseBenchArgs(['--smoke', 'exact|default'], ROWS)).toEqual({
      args: { help: false, smoke: true, only: ['exact', 'default'], port: null },
    });
    expect(parseBenchArgs(['--help'], ROWS)).toEqual({ args: { help: true } });
  });

  it('--port moves the servers: an integer port, the next one free for the preview', () => {
    for (const argv of [
      ['--port', '5196', 'exact'],
      ['--port=5196', 'exact'],
    ])
      expect(parseBenchArgs(argv, ROWS)).toEqual({ args: { help: false, smoke: false, only: ['exact'], port: 5196 } });
    for (const bad of [['--port'], ['--port', 'x'], ['--port=80'], ['--port=65535'], ['--port=5196.5']]) {
      const r = parseBenchArgs(bad, ROWS);
      expect('error' in r && r.error).toMatch(/^--port must be an integer from 1024 to 65534/);
    }
  });

  it('an unknown flag is an error naming it and listing the flags and rows', () => {
    const r = parseBenchArgs(['--bogus'], ROWS);
    expect('error' in r && r.error).toContain('"--bogus"');
    for (const flag of Object.keys(BENCH_FLAGS)) expect('error' in r && r.error).toContain(flag);
    for (const row of ROWS) expect('error' in r && r.error).toContain(row);
  });

  it('a text that picks no row is an error naming it (and only it) and listing the rows', () => {
    const r = parseBenchArgs(['exact|fourrier'], ROWS);
    expect('error' in r && r.error).toMatch(/^no row named "fourrier"\n/);
    for (const row of ROWS) expect('error' in r && r.error).toContain(row);
    expect('error' in parseBenchArgs(['exact||table'], ROWS)).toBe(true);
    expect('error' in parseBenchArgs(['exact', 'table'], ROWS)).toBe(true);
  });

  it(
    'npm run bench -- --bogus exits 2 before starting anything, naming the flag',
    () => {
      const r = spawnSync('node_modules/.bin/tsx', ['scripts/bench.ts', '--bogus'], { cwd: ROOT, encoding: 'utf8' });
      expect(r.status).toBe(2);
      expect(r.stderr).toContain('unknown flag "--bogus"');
      expect(r.stderr).toContain('--smoke');
      expect(r.stderr).not.toContain('[bench');
      expect(r.stdout).toBe('');
    },
    SPAWN_TIMEOUT_MS,
  );
});

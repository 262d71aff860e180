/**
 * The render command's process glue without a browser: bad input exits 2 with one line naming the
 * option and writes nothing; no Chromium exits 3 with one line on how to get one. (Renders that
 * launch Chromium are tests/e2e/render.spec.ts.)
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** Each spawn starts tsx (~0.5 s); allow for a loaded machine. */
const SPAWN_TIMEOUT_MS = 60_000;

function render(args: string[], env: NodeJS.ProcessEnv = {}) {
  const r = spawnSync('node_modules/.bin/tsx', ['scripts/render.ts', ...args], {
    cwd: ROOT,
    encoding: 'utf8',
    env: { ...process.env, ...env },
  });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('render command: exit statuses', () => {
  it(
    'bad options exit 2 with one line naming the option and its range, and write nothing',
    () => {
      const dir = mkdtempSync(join(tmpdir(), 'render-bad-'));
      const out = join(dir, 'view.png');
      writeFileSync(join(dir, 'views.json'), JSON.stringify([{ out: join(dir, 'a.png') }, { out, nFilm: 5 }]));
      const runs: [string[], string][] = [
        [['--thickness', '-5', '--out', out], 'render: --thickness: "-5" is not allowed; expected a number in [0, 20000] nm\n'],
        [['--width', '99999', '--out', out], 'render: --width: "99999" is not allowed; expected a whole number in [16, 4096] CSS px\n'],
        [
          ['--cases', join(dir, 'views.json')],
          'render: case at index 1: nFilm: 5 is not allowed; expected a number in [1, 4], water, cauchy:A,B[,C], Au, Ag, Cu, Al, Ti, Fe, Cr, Ni, TiO2, Fe3O4, SiO2 or complex:n,k (n in [0.01, 10], k in [0, 100]) (here n is 5, above 4)\n',
        ],
        [['--out', join(dir, 'no-such-folder', 'view.png')], 'render: --out: '],
        [['--time-lapse', '3:1:1', '--out', out], 'render: --time-lapse: "3:1:1" is not allowed; expected START:END:STEP'],
        [['--time-lapse', '0:3:1', '--time', '1', '--out', out], 'render: --time-lapse: not allowed with --time'],
        [['--time-lapse', '0:3:1', '--out', join(dir, 'no-such-folder', 'life.png')], 'render: --out: '],
        [['--thicknessRange', '600', '--out', out], 'render: --thicknessRange: unknown flag; it is spelt --thickness-range\n'],
      ];
      for (const [args, line] of runs) {
        const r = render(args);
        expect(r.status, args.join(' ')).toBe(2);
        expect(r.stderr.startsWith(line), r.stderr).toBe(true);
        expect(r.stderr.split('\n')).toHaveLength(2);
        expect(r.stdout).toBe('');
      }
      expect(readdirSync(dir)).toEqual(['views.json']);
    },
    SPAWN_TIMEOUT_MS * 8,
  );

  it(
    'no Chromium (CHROME_PATH names a missing file) exits 3 with one line on how to get one, and writes nothing',
    () => {
      const dir = mkdtempSync(join(tmpdir(), 'render-nobrowser-'));
      const out = join(dir, 'view.png');
      writeFileSync(out, 'an older picture');
      const r = render(['--out', out], { CHROME_PATH: join(dir, 'no-chromium') });
      expect(r.status).toBe(3);
      expect(r.stderr).toMatch(
        /^render: CHROME_PATH=.*no-chromium does not exist\. Install one \(Debian: apt-get install -y chromium;.*set CHROME_PATH\.\n$/,
      );
      expect(r.stdout).toBe('');
      expect(readdirSync(dir)).toEqual(['view.png']);
      expect(readFileSync(out, 'utf8')).toBe('an older picture');
    },
    SPAWN_TIMEOUT_MS,
  );

  it(
    '--help lists every view option with its range and default',
    () => {
      const r = render(['--help']);
      expect(r.status).toBe(0);
      expect(r.stdout).toContain('--thickness           thickness (nm): a number in [0, 20000] nm (550)');
      expect(r.stdout).toContain('--thickness-range     range (nm): a number in [0, 20000] nm (800)');
      expect(r.stdout).toContain('--n-film              n film: ');
      expect(r.stdout).toContain('--progress');
      expect(r.stdout).toContain('--probe');
      expect(r.stdout).toContain('--time-lapse START:END:STEP');
      expect(r.stdout).toContain('--frame-ms MS         how long each frame is shown: a whole number in [20, 10000] ms (100)');
    },
    SPAWN_TIMEOUT_MS,
  );
});

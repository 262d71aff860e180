import { spawnSync } from 'node:child_process';
import { chmodSync, mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium, expect, test } from '@playwright/test';
import { PNG } from 'pngjs';
import { findChromium } from '../../scripts/chromium.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';

/**
 * `npm run render` with a browser: one `--cases` run of three views, launched through a wrapper
 * that counts Chromium's launches. Expected colours come from src/physics (referenceColor.ts).
 */

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** Three renders take ~15 s here on SwiftShader (Vite and Chromium started once); room for a machine many times slower. */
const RUN_TIMEOUT_MS = 540_000;

/** A uniform 450 nm film seen head-on with nothing behind it: its centre is the reference colour. */
const FILM = { field: 'uniform', thickness: 450, env: 'none', sides: 'front', animate: 0 };

const pixel = (png: PNG, x: number, y: number) => [...png.data.subarray((y * png.width + x) * 4, (y * png.width + x) * 4 + 3)];
/** Whether every pixel of the box [x0, x1) × [y0, y1) is black. */
function allBlack(png: PNG, x0: number, y0: number, x1: number, y1: number): boolean {
  for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) if (pixel(png, x, y).some((v) => v !== 0)) return false;
  return true;
}

test('render --cases: three views, one browser launch, the reference colour at the centre', () => {
  test.setTimeout(RUN_TIMEOUT_MS + 60_000);
  const dir = mkdtempSync(join(tmpdir(), 'render-cases-'));
  // Chromium launched through a script that notes each launch (its own child processes start the binary directly).
  const search = findChromium();
  if (!('found' in search)) throw new Error(search.missing);
  const chromiumPath = search.found.executablePath ?? chromium.executablePath();
  const launches = join(dir, 'launches.log');
  const wrapper = join(dir, 'chromium-counted');
  writeFileSync(wrapper, `#!/bin/sh\necho launched >> '${launches}'\nexec '${chromiumPath}' "$@"\n`);
  chmodSync(wrapper, 0o755);

  const views = [
    { out: join(dir, 'film.png'), ...FILM },
    { out: join(dir, 'small.png'), width: 200, height: 150, scale: 2 },
    { out: join(dir, 'film-plots.png'), ...FILM, plots: true },
  ];
  writeFileSync(views[2]!.out, 'an older picture, replaced whole');
  writeFileSync(join(dir, 'views.json'), JSON.stringify(views));
  const r = spawnSync('node_modules/.bin/tsx', ['scripts/render.ts', '--cases', join(dir, 'views.json')], {
    cwd: ROOT,
    encoding: 'utf8',
    env: { ...process.env, CHROME_PATH: wrapper },
    timeout: RUN_TIMEOUT_MS,
  });
  console.log(`render --cases: status ${r.status}\n${r.stdout}${r.stderr}`);
  expect(r.status).toBe(0);
  expect(r.stderr).toBe('');
  expect(readFileSync(launches, 'utf8')).toBe('launched\n');
  expect(readdirSync(dir).sort()).toEqual(['chromium-counted', 'film-plots.png', 'film.png', 'launches.log', 'small.png', 'views.json']);

  const lines = r.stdout
    .trimEnd()
    .split('\n')
    .map((line) => JSON.parse(line) as { out: string; width: number; height: number; ms: number });
  expect(lines.map((l) => l.out)).toEqual(views.map((v) => v.out));
  const pngs: PNG[] = views.map((v) => PNG.sync.read(readFileSync(v.out)));
  lines.forEach((line, i) => {
    expect([line.width, line.height]).toEqual([pngs[i]!.width, pngs[i]!.height]);
    expect(line.ms).toBeGreaterThan(0);
  });
  const [film, small, withPlots] = pngs as [PNG, PNG, PNG];
  expect([film.width, film.height, small.width, small.height]).toEqual([640, 480, 400, 300]);

  const centre = pixel(film, 320, 240);
  const expected = reference8({ thicknessNm: 450 }, 'D65');
  console.log(`render centre: ${centre} reference ${expected}`);
  expect(worstCodeDifference(centre, expected)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  // No panel (top right) and no plots (top left) over the black background; with --plots, the plots are drawn.
  expect(allBlack(film, 440, 0, 640, 40)).toBe(true);
  expect(allBlack(film, 0, 0, 120, 120)).toBe(true);
  expect(allBlack(withPlots, 0, 0, 120, 120)).toBe(false);
  expect(pixel(withPlots, 320, 240)).toEqual(centre);
});

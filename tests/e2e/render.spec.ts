import { spawnSync } from 'node:child_process';
import { chmodSync, mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium, expect, test } from '@playwright/test';
import { PNG } from 'pngjs';
import UPNG from 'upng-js';
import { findChromium } from '../../scripts/chromium.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';

/**
 * `npm run render` with a browser: one `--cases` run of three views, launched through a wrapper
 * that counts Chromium's launches (expected colours from src/physics, referenceColor.ts); and a
 * time-lapse, each of whose frames is the still the same command renders at that time.
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

/** A wrapper around Chromium that notes each launch in `dir`/launches.log (its own child processes start the binary directly). */
function countedChromium(dir: string): { wrapper: string; launches: string } {
  const search = findChromium();
  if (!('found' in search)) throw new Error(search.missing);
  const chromiumPath = search.found.executablePath ?? chromium.executablePath();
  const launches = join(dir, 'launches.log');
  const wrapper = join(dir, 'chromium-counted');
  writeFileSync(wrapper, `#!/bin/sh\necho launched >> '${launches}'\nexec '${chromiumPath}' "$@"\n`);
  chmodSync(wrapper, 0o755);
  return { wrapper, launches };
}

/** `npm run render -- ...args` through the counting wrapper; its JSON lines. */
function runRender(args: string[], wrapper: string): Record<string, unknown>[] {
  const r = spawnSync('node_modules/.bin/tsx', ['scripts/render.ts', ...args], {
    cwd: ROOT,
    encoding: 'utf8',
    env: { ...process.env, CHROME_PATH: wrapper },
    timeout: RUN_TIMEOUT_MS,
  });
  console.log(`render ${args.join(' ')}: status ${r.status}\n${r.stdout}${r.stderr}`);
  expect(r.status).toBe(0);
  expect(r.stderr).toBe('');
  return r.stdout
    .trimEnd()
    .split('\n')
    .map((line) => JSON.parse(line) as Record<string, unknown>);
}

test('render --cases: three views, one browser launch, the reference colour at the centre', () => {
  test.setTimeout(RUN_TIMEOUT_MS + 60_000);
  const dir = mkdtempSync(join(tmpdir(), 'render-cases-'));
  const { wrapper, launches } = countedChromium(dir);

  const views = [
    { out: join(dir, 'film.png'), ...FILM },
    { out: join(dir, 'small.png'), width: 200, height: 150, scale: 2 },
    { out: join(dir, 'film-plots.png'), ...FILM, plots: true },
  ];
  writeFileSync(views[2]!.out, 'an older picture, replaced whole');
  writeFileSync(join(dir, 'views.json'), JSON.stringify(views));
  const lines = runRender(['--cases', join(dir, 'views.json')], wrapper) as { out: string; width: number; height: number; ms: number }[];
  expect(readFileSync(launches, 'utf8')).toBe('launched\n');
  expect(readdirSync(dir).sort()).toEqual(['chromium-counted', 'film-plots.png', 'film.png', 'launches.log', 'small.png', 'views.json']);

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

/** The flowing film of a small grid, frozen (animate 0) at each time: the command line of both the stills and the time-lapse. */
const FLOW = ['--field', 'flow', '--grid', '16', '--seed', '3', '--width', '160', '--height', '120'];
const TIMES_S = [0, 1, 2];

/** How many bytes of two RGBA frames differ. */
function bytesDiffering(a: Uint8Array, b: Uint8Array): number {
  let n = 0;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) n++;
  return n;
}

// The WebP encoder's frames are its input's (tests/unit/render/encodeAnimation.test.ts): one format here, end to end.
test('render --time-lapse: one launch, each frame of the APNG the still at its time, the film evolving', () => {
  test.setTimeout(2 * RUN_TIMEOUT_MS + 60_000);
  const dir = mkdtempSync(join(tmpdir(), 'render-lapse-'));
  const { wrapper, launches } = countedChromium(dir);
  // The stills, one --cases run; the time-lapse, one run.
  writeFileSync(join(dir, 'stills.json'), JSON.stringify(TIMES_S.map((t) => ({ out: join(dir, `still-${t}.png`), time: t, animate: 0 }))));
  runRender(['--cases', join(dir, 'stills.json'), ...FLOW], wrapper);
  const lapse = `${TIMES_S[0]}:${TIMES_S.at(-1)}:1`;
  const [apngLine] = runRender([...FLOW, '--time-lapse', lapse, '--frame-ms', '250', '--out', join(dir, 'life.png')], wrapper);
  expect(readFileSync(launches, 'utf8')).toBe('launched\n'.repeat(2));
  expect(apngLine).toMatchObject({ out: join(dir, 'life.png'), format: 'apng', frames: 3, frameMs: 250, width: 160, height: 120 });

  const stills = TIMES_S.map((t) => PNG.sync.read(readFileSync(join(dir, `still-${t}.png`))).data);
  const apng = UPNG.decode(Uint8Array.from(readFileSync(join(dir, 'life.png'))).buffer);
  expect([apng.width, apng.height, apng.frames.map((f) => f.delay)]).toEqual([160, 120, [250, 250, 250]]);
  const apngFrames = UPNG.toRGBA8(apng).map((frame) => new Uint8Array(frame));
  // The encoder is lossless and the frozen view is deterministic, so every frame is its still exactly.
  TIMES_S.forEach((t, i) => {
    expect(bytesDiffering(apngFrames[i]!, stills[i]!), `APNG frame at ${t} s`).toBe(0);
  });
  // The film flows: no two frames in a row are the same picture.
  for (let i = 1; i < TIMES_S.length; i++) expect(bytesDiffering(apngFrames[i - 1]!, apngFrames[i]!)).toBeGreaterThan(0);
});

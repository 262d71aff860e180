/**
 * `npm run bench`: the float64 reference's speed in Node, then every film-colour method in
 * headless Chromium (frame times, table rebuild, first frame, ΔE00 against src/physics), the
 * built demo's size, first frame and render-on-demand counts. Prints Markdown and writes
 * bench-results.json (git-ignored). Benchmarks measure; the tests check correctness.
 */
import { writeFileSync } from 'node:fs';
import { chromium } from '@playwright/test';
import { createServer, preview } from 'vite';
import { chromiumLaunchOptions } from './chromium.ts';
import { FIXED_GRID, STRESS_GRID, gridError, referenceXyz } from './bench/errorGrids.ts';
import { FRAME_BUDGET_MS, FRAMES, SIZES, runRow, warmUp } from './bench/browserRows.ts';
import { buildAndMeasure, ELEMENT_BUNDLE } from './bench/bundleSize.ts';
import { PANEL_CHANGES, demoPageFigures } from './bench/demoPage.ts';
import { referenceSpeed, referenceSpeedMarkdown } from './bench/referenceSpeed.ts';
import { ROWS } from './bench/rows.ts';
import type { ParityGroup } from '../src/render/parityCase.ts';
import type { Xyz } from '../src/physics/spectralWeights.ts';
import { rowsMarkdown } from './bench/rowsMarkdown.ts';

/** Ports of the benchmark's own servers (5173, 5180, 5181 belong to the dev server and the test suites). */
const DEV_PORT = 5192;
const PREVIEW_PORT = 5193;
const started = performance.now();
const log = (what: string) => console.error(`[bench ${((performance.now() - started) / 1000).toFixed(0)} s] ${what}`);

/** `npm run bench -- <text>[|<text>…]` runs only the rows whose name contains one of the texts (the floor always runs). */
const only = process.argv[2]?.split('|');
const selected = ROWS.filter((r, i) => i === 0 || !only || only.some((text) => r.name.includes(text)));
const reference = referenceSpeed();
console.log(`${referenceSpeedMarkdown(reference)}\n`);
log('reference speed done; computing the reference colours of the error grids');
/** The grids for a row's film (the soap film n 1.33, or the row's own index) and their reference colours, computed once per film when first needed. */
const gridsByFilm = new Map<string, { grids: ParityGroup[]; reference: Xyz[][] | null }>();
function gridsOf(row: (typeof ROWS)[number]): { grids: ParityGroup[]; reference: Xyz[][] | null } {
  const key = JSON.stringify(row.settings.nFilm);
  const entry = gridsByFilm.get(key) ?? {
    grids: [FIXED_GRID, STRESS_GRID].map((g) => ({ ...g, nFilm: row.settings.nFilm })),
    reference: null,
  };
  if (row.measuresError) entry.reference ??= entry.grids.map(referenceXyz);
  gridsByFilm.set(key, entry);
  return entry;
}

const server = await createServer({ logLevel: 'silent', server: { port: DEV_PORT, strictPort: true, host: '127.0.0.1' } });
await server.listen();
const browser = await chromium.launch(chromiumLaunchOptions());
await warmUp(browser, `http://127.0.0.1:${DEV_PORT}`);
const rows = [];
try {
  for (const row of selected) {
    const { grids, reference } = gridsOf(row);
    const result = await runRow(browser, `http://127.0.0.1:${DEV_PORT}`, row, grids);
    const errors = reference ? grids.map((g, i) => gridError(g, reference[i]!, result.xyz[i]!)) : null;
    log(
      `${row.name}: ${JSON.stringify({ frames: result.frames, table: result.tableBuildMs, errors: errors?.map((e) => [e.max.toFixed(2), e.worst]) })}`,
    );
    rows.push({ name: row.name, settings: row.settings, quality: row.quality, ...result, xyz: undefined, errors });
  }
} finally {
  await server.close();
}
log('building the demo');
const bundle = await buildAndMeasure();
const previewServer = await preview({ logLevel: 'silent', preview: { port: PREVIEW_PORT, strictPort: true, host: '127.0.0.1' } });
let demo;
try {
  demo = await demoPageFigures(browser, `http://127.0.0.1:${PREVIEW_PORT}`);
} finally {
  await new Promise((resolve) => previewServer.httpServer.close(resolve));
  await browser.close();
}

const kb = (bytes: number) => `${(bytes / 1024).toFixed(1)} KiB`;
console.log(rowsMarkdown(rows, { sizes: SIZES, frames: FRAMES, frameBudgetMs: FRAME_BUDGET_MS }));
console.log(`
| built demo (vite build, served by vite preview) | value |
|---|---|
| demo JavaScript, gzipped (all of dist's JS but the element and the environments) | ${kb(bundle.demoGzipBytes)} |
| element \`${ELEMENT_BUNDLE}\`, gzipped | ${bundle.elementGzipBytes === null ? 'not built yet' : kb(bundle.elementGzipBytes)} |
| each HDR environment's module, gzipped (fetched only when shown) | ${kb(Math.min(...bundle.environmentGzipBytes))} – ${kb(Math.max(...bundle.environmentGzipBytes))} |
| first frame (navigation start → first frame read back, 1280×720) | ${demo.firstFrameMs.toFixed(0)} ms |
| frames drawn / tables built in 1 s: still (\`animate=0\`) | ${demo.still.frames} / ${demo.still.tableBuilds} |
| … swirl animating | ${demo.animating.frames} / ${demo.animating.tableBuilds} |
| … canvas hidden (display: none) | ${demo.canvasHidden.frames} / ${demo.canvasHidden.tableBuilds} |
| … page hidden | ${demo.pageHidden.frames} / ${demo.pageHidden.tableBuilds} |
| frame while the swirl animates (1280×720, median) | ${demo.frameMs.toFixed(0)} ms |
${PANEL_CHANGES.map(([name], i) => `| panel: ${name} → next frame / → shown in full, plots included (median of 6) | ${demo.panelChangeMs[i]!.toFixed(0)} ms (${(demo.panelChangeMs[i]! / demo.frameMs).toFixed(1)}× the frame) / ${demo.panelChangeFullMs[i]!.toFixed(0)} ms |`).join('\n')}`);
writeFileSync(
  'bench-results.json',
  JSON.stringify({ reference, rows, bundle, demo, seconds: (performance.now() - started) / 1000 }, null, 2),
);
log('done; bench-results.json written');

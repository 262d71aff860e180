/**
 * `npm run bench`: the float64 reference's speed in Node, then every film-colour method in
 * headless Chromium (frame times, table rebuild, first frame, ΔE00 against src/physics), the
 * built demo's size, first frame and render-on-demand counts. Prints Markdown and writes
 * bench-results.json (git-ignored). Benchmarks measure; the tests check correctness.
 */
import { writeFileSync } from 'node:fs';
import { chromium } from '@playwright/test';
import type { FilmIndex } from '../src/physics/filmIndex.ts';
import { createServer, preview } from 'vite';
import { chromiumLaunchOptions } from './chromium.ts';
import { FIXED_GRID, STRESS_GRID, gridError, referenceXyz } from './bench/errorGrids.ts';
import { FRAME_BUDGET_MS, FRAMES, SIZES, runRow, warmUp } from './bench/browserRows.ts';
import { buildAndMeasure, ELEMENT_BUNDLE } from './bench/bundleSize.ts';
import { PANEL_CHANGES, demoPageFigures } from './bench/demoPage.ts';
import { materialFigures } from './bench/materialFigures.ts';
import { referenceSpeed, referenceSpeedMarkdown } from './bench/referenceSpeed.ts';
import { ROWS } from './bench/rows.ts';
import type { ParityGroup } from './harness/parityCase.ts';
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
/** The spectral material's figures (the example page, the app bundle) run with every row, or with `materials`. */
const MATERIALS_ROW = 'materials page: spectral film against three.js iridescence';
const runMaterials = !only || only.some((text) => MATERIALS_ROW.includes(text));
const reference = referenceSpeed();
console.log(`${referenceSpeedMarkdown(reference)}\n`);
log('reference speed done; computing the reference colours of the error grids');
/** The grids for a film (the soap film n 1.33, or a row's own index) and, if asked for, their reference colours, computed once per film when first needed. */
const gridsByFilm = new Map<string, { grids: ParityGroup[]; reference: Xyz[][] | null }>();
function gridsOf(nFilm: FilmIndex, withReference: boolean): { grids: ParityGroup[]; reference: Xyz[][] | null } {
  const key = JSON.stringify(nFilm);
  const entry = gridsByFilm.get(key) ?? { grids: [FIXED_GRID, STRESS_GRID].map((g) => ({ ...g, nFilm })), reference: null };
  if (withReference) entry.reference ??= entry.grids.map(referenceXyz);
  gridsByFilm.set(key, entry);
  return entry;
}

const server = await createServer({ logLevel: 'silent', server: { port: DEV_PORT, strictPort: true, host: '127.0.0.1' } });
await server.listen();
const browser = await chromium.launch(chromiumLaunchOptions());
await warmUp(browser, `http://127.0.0.1:${DEV_PORT}`);
const rows = [];
let materials = null;
try {
  for (const row of selected) {
    const { grids, reference } = gridsOf(row.settings.nFilm, row.measuresError);
    const result = await runRow(browser, `http://127.0.0.1:${DEV_PORT}`, row, grids);
    const errors = reference ? grids.map((g, i) => gridError(g, reference[i]!, result.xyz[i]!)) : null;
    log(
      `${row.name}: ${JSON.stringify({ frames: result.frames, table: result.tableBuildMs, errors: errors?.map((e) => [e.max.toFixed(2), e.worst]) })}`,
    );
    rows.push({ name: row.name, settings: row.settings, quality: row.quality, ...result, xyz: undefined, errors });
  }
  if (runMaterials) {
    // The material's film is three's iridescenceIOR, one number: the soap film's grids.
    const soap = gridsOf(FIXED_GRID.nFilm, true);
    materials = await materialFigures(browser, `http://127.0.0.1:${DEV_PORT}`, soap.grids, soap.reference!);
    log(`${MATERIALS_ROW}: ${JSON.stringify(materials)}`);
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
| navigation start → first frame shown / → first frame shown in full (1280×720) | ${demo.firstFrameMs.toFixed(0)} ms / ${demo.firstCompleteFrameMs.toFixed(0)} ms |
| frames drawn / tables built in 1 s: still (\`animate=0\`) | ${demo.still.frames} / ${demo.still.tableBuilds} |
| … swirl animating | ${demo.animating.frames} / ${demo.animating.tableBuilds} |
| … canvas hidden (display: none) | ${demo.canvasHidden.frames} / ${demo.canvasHidden.tableBuilds} |
| … page hidden | ${demo.pageHidden.frames} / ${demo.pageHidden.tableBuilds} |
| frame interval while the swirl animates (1280×720, median) | ${demo.frameMs.toFixed(0)} ms |
${PANEL_CHANGES.map(([name], i) => `| panel: ${name} → longest gap between frames shown, median of 6 / worst (× the frame interval); → shown in full, plots included | ${demo.panelLongestGap[i]!.median.toFixed(1)}× / ${demo.panelLongestGap[i]!.max.toFixed(1)}×; ${demo.panelChangeFullMs[i]!.toFixed(0)} ms |`).join('\n')}`);
if (materials) {
  const m = materials;
  console.log(`
| ${MATERIALS_ROW} | value |
|---|---|
| example scene (materials.html, ${m.width}×${m.height}), median of ${m.frames} frames: three.js iridescence / spectral (\`table\`) | ${m.frameMs['three.js'].toFixed(1)} / ${m.frameMs.spectral.toFixed(1)} ms (${(m.frameMs.spectral / m.frameMs['three.js']).toFixed(2)}×) |
| minimal three.js app with an iridescent MeshPhysicalMaterial, gzipped: as it is / made spectral | ${kb(m.threeAppGzipBytes)} / ${kb(m.spectralAppGzipBytes)} (+${kb(m.spectralAppGzipBytes - m.threeAppGzipBytes)}) |
${Object.entries(m.gridErrors)
  .map(
    ([mode, [fixed, stress]]) =>
      `| the whole material's pixels, \`${mode}\`: ΔE00 fixed grid / stress grid (max / p99 / mean), films > 0 nm [all, 0 nm included] | ${[fixed!, stress!].map((e) => `${e.films.max.toFixed(3)} / ${e.films.p99.toFixed(3)} / ${e.films.mean.toFixed(3)} [${e.all.max.toFixed(1)} / ${e.all.p99.toFixed(2)} / ${e.all.mean.toFixed(3)}]`).join(' — ')} |`,
  )
  .join('\n')}`);
}
writeFileSync(
  'bench-results.json',
  JSON.stringify({ reference, rows, bundle, demo, materials, seconds: (performance.now() - started) / 1000 }, null, 2),
);
log('done; bench-results.json written');

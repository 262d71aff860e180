/** A run's results as the Markdown that `npm run bench` prints and docs/benchmarks.md holds. */
import type { BenchResults } from './benchResults.ts';
import { ELEMENT_BUNDLE } from './bundleSize.ts';
import { ENTRY_BYTES_GOALS, type EntryBytes } from './entryBytes.ts';
import { defaultViewMarkdown } from './defaultView.ts';
import { LONG_TASK_MS, PANEL_CHANGES } from './panelChanges.ts';
import { flowSpeedMarkdown } from './flowSpeed.ts';
import { referenceSpeedMarkdown } from './referenceSpeed.ts';
import { nodeMarkdown } from './nodeMarkdown.ts';
import { MATERIALS_ROW } from './rows.ts';
import { rowsMarkdown } from './rowsMarkdown.ts';

const kb = (bytes: number) => `${(bytes / 1024).toFixed(1)} KiB`;

function builtMarkdown(r: BenchResults): string {
  const lines = ['| built demo and package | value |', '|---|---|'];
  const b = r.bundle;
  if (b)
    lines.push(
      `| demo JavaScript, gzipped (all of dist's JS but the element, the environments and the example page) | ${kb(b.demoGzipBytes)} |`,
      `| element \`${ELEMENT_BUNDLE}\`, gzipped | ${b.elementGzipBytes === null ? 'not built' : kb(b.elementGzipBytes)} |`,
      `| each HDR environment's module, gzipped (fetched only when shown) | ${kb(Math.min(...b.environmentGzipBytes))} – ${kb(Math.max(...b.environmentGzipBytes))} |`,
    );
  const p = r.package;
  if (p)
    lines.push(`| package tarball (\`npm pack\`), ${p.files} files: packed / unpacked | ${kb(p.tarballBytes)} / ${kb(p.unpackedBytes)} |`);
  const d = r.demo;
  const { width, height, panelTwice } = r.plan.demo;
  if (d)
    lines.push(
      `| navigation start → first frame drawn / → first frame drawn in full, each read back as the page marks it (${width}×${height}, vite preview) | ${d.firstFrameMs.toFixed(0)} ms / ${d.firstCompleteFrameMs.toFixed(0)} ms |`,
      `| frames drawn / tables built in 1 s: still (\`animate=0\`) | ${d.still.frames} / ${d.still.tableBuilds} |`,
      `| … swirl animating | ${d.animating.frames} / ${d.animating.tableBuilds} |`,
      `| … canvas hidden (display: none) | ${d.canvasHidden.frames} / ${d.canvasHidden.tableBuilds} |`,
      `| … page hidden | ${d.pageHidden.frames} / ${d.pageHidden.tableBuilds} |`,
      ...PANEL_CHANGES.map(([name], i) => {
        const c = d.panel[i]!;
        return `| panel: ${name} ${panelTwice ? 'there, back, there and back again' : 'there and back'} → programs linked (first / back / second time); long tasks over ${LONG_TASK_MS} ms (count, longest); table texels drawn the first time; → shown in full, plots included (median) | ${c.programs.first} / ${c.programs.back} / ${c.programs.second ?? '—'}; ${c.longTasks.count}, ${c.longTasks.maxMs.toFixed(0)} ms; ${c.texels}; ${c.fullMs.toFixed(0)} ms |`;
      }),
      `| the GPU compiles in parallel (KHR_parallel_shader_compile) | ${d.parallelCompile ? 'yes' : 'no: every new program is compiled blocking, so a change that needs one is a long task'} |`,
    );
  return lines.join('\n');
}

/** An entry's rows: what it adds to three's minimal app on its renderer, loaded at start and built in all. */
const entryBytesMarkdown = (e: EntryBytes): string =>
  (['eager', 'emitted'] as const)
    .map((k) => {
      const [three, spectral] = [e.three[`${k}GzipBytes`], e.spectral[`${k}GzipBytes`]];
      return `| \`${e.entry}\`: three.js's minimal app (${e.renderer}, an iridescent ${e.material}), gzipped ${k === 'eager' ? 'JavaScript loaded at start (the entry chunk and its static imports)' : 'files the build emits'}: as it is / made spectral | ${kb(three)} / ${kb(spectral)} (+${kb(spectral - three)}; goal ≤ +${kb(ENTRY_BYTES_GOALS[k])}) |`;
    })
    .join('\n');

function materialsMarkdown(r: BenchResults): string {
  const m = r.materials;
  if (!m) return '';
  return `| ${MATERIALS_ROW} | value |
|---|---|
| example scene (materials.html, ${m.width}×${m.height}), median of ${m.frames} frames: three.js iridescence / spectral (\`table\`) | ${m.frameMs['three.js'].toFixed(1)} / ${m.frameMs.spectral.toFixed(1)} ms (${(m.frameMs.spectral / m.frameMs['three.js']).toFixed(2)}×) |
${m.entryBytes.map(entryBytesMarkdown).join('\n')}
${Object.entries(m.gridErrors)
  .map(
    ([mode, [fixed, stress]]) =>
      `| the whole material's pixels, \`${mode}\`: ΔE00 fixed grid / stress grid (max / p99 / mean), films > 0 nm [all, 0 nm included] | ${[fixed!, stress!].map((e) => `${e.films.max.toFixed(3)} / ${e.films.p99.toFixed(3)} / ${e.films.mean.toFixed(3)} [${e.all.max.toFixed(1)} / ${e.all.p99.toFixed(2)} / ${e.all.mean.toFixed(3)}]`).join(' — ')} |`,
  )
  .join('\n')}`;
}

const stagesMarkdown = (r: BenchResults): string =>
  [
    '| stage | s |',
    '|---|---|',
    ...Object.entries(r.stageSeconds).map(([name, s]) => `| ${name} | ${s.toFixed(1)} |`),
    `| whole run | ${r.seconds.toFixed(0)} |`,
  ].join('\n');

export function benchMarkdown(r: BenchResults): string {
  return [
    r.reference ? referenceSpeedMarkdown(r.reference, r.machine.node) : '',
    r.rows.length > 0 ? rowsMarkdown(r.rows, r.plan) : '',
    r.flowGpu || r.flowTwin ? flowSpeedMarkdown(r.flowGpu, r.flowTwin, r.plan.flowSpeed) : '',
    builtMarkdown(r),
    r.defaultView ? defaultViewMarkdown(r.defaultView, r.plan.defaultView) : '',
    materialsMarkdown(r),
    r.node ? nodeMarkdown(r.node) : '',
    stagesMarkdown(r),
    r.machine.webgl,
  ]
    .filter((part) => part !== '')
    .join('\n\n');
}

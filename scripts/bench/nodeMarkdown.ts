/**
 * The node figures (nodeFigures.ts) as Markdown, one column per backend of WebGPURenderer, and
 * what a run's node figures lack.
 */
import type { GridError } from './errorGrids.ts';
import { type ChangeSetting, type NodeBackendFigures, type NodeFigures, changeSettings } from './nodeFigures.ts';
import {
  NODE_BACKENDS,
  NODE_BACKEND_LABELS,
  NODE_GRID_MODES,
  NODE_MATERIALS,
  NODE_MATERIAL_NAMES,
  NODE_OPTION_CHANGES,
} from './nodeMaterials.ts';
import { LONG_TASK_MS } from './panelChanges.ts';
import { NODE_ROW } from './rows.ts';

/** A setting of the option changes, as the table names it. */
const settingLabel = (s: ChangeSetting) => `${s.width}×${s.height}${s.gpuApart ? ', GPU process apart' : ''}`;

const ms = (x: number) => (x >= 100 ? x.toFixed(0) : x.toFixed(1));
const stats = (e: GridError) => `${e.max.toFixed(3)} / ${e.p99.toFixed(3)} / ${e.mean.toFixed(3)}`;

/** A table row: its legend, then one cell per backend. */
const row = (legend: string, backends: readonly NodeBackendFigures[], cell: (b: NodeBackendFigures) => string) =>
  `| ${legend} | ${backends.map(cell).join(' | ')} |`;

export function nodeMarkdown(n: NodeFigures): string {
  const b = n.backends;
  const frames = NODE_MATERIAL_NAMES.map((name, i) =>
    row(
      i === 0
        ? `a sphere filling the view's height (${n.width}×${n.height}, a constant white environment and a directional light), median of ${n.frames} frames ([1]: one, as the first outlasted the frame budget), ms (× the floor, on the same backend in the same run): ${NODE_MATERIALS[name].label}`
        : `… ${NODE_MATERIALS[name].label}`,
      b,
      (f) => {
        const t = f.frames[name];
        return `${ms(t.medianMs)} (${(t.medianMs / f.frames.floor.medianMs).toFixed(2)}×)${t.count < n.frames ? ` [${t.count}]` : ''}`;
      },
    ),
  );
  const errors = NODE_GRID_MODES.map((mode) =>
    row(`the spectral film, \`${mode}\`: ΔE00 against the float64 reference, fixed grid — stress grid (max / p99 / mean)`, b, (f) =>
      f.gridErrors[mode].map(stats).join(' — '),
    ),
  );
  const threes = row(
    "three.js's node iridescence, the whole material's pixels (scripts/harness/materialGridScene.ts), films > 0 nm: ΔE00 against the float64 reference, fixed grid — stress grid (max / p99 / mean)",
    b,
    (f) => f.threeGridErrors.map(stats).join(' — '),
  );
  const settings = changeSettings(n).map(settingLabel).join(' · ');
  const changes = NODE_OPTION_CHANGES.map(([what], i) =>
    row(
      i === 0
        ? `option changes on the \`table\` sphere at ${settings} (a small size: a frame the CPU rasteriser draws well within ${LONG_TASK_MS} ms; GPU process apart: held to a core of its own, the page's renderer to the other, scripts/bench/gpuApart.ts), one after another, each drawn until whenSpectralReady resolves: the main thread's longest task (in brackets, the thread's own time in it: the rest it waited on the GPU process or was not scheduled), its tasks over ${LONG_TASK_MS} ms and the most the thread itself ran in one task, from the change to its frame drawn with the film ready (goal: longest ≤ ${LONG_TASK_MS} ms, none over); change → that frame: ${what}`
        : `… ${what}`,
      b,
      (f) =>
        f.changes
          .map(({ figures }) => {
            const c = figures[i]!;
            return `${c.longestMs.toFixed(0)} ms (${c.longestThreadMs.toFixed(0)}), ${c.over} over, own ≤ ${c.mostThreadMs.toFixed(0)} ms; ${ms(c.toFrameMs)} ms`;
          })
          .join(' · '),
    ),
  );
  return [
    `| ${NODE_ROW} | ${b.map((f) => NODE_BACKEND_LABELS[f.backend]).join(' | ')} |`,
    `|---|${b.map(() => '---|').join('')}`,
    ...frames,
    ...errors,
    threes,
    ...changes,
  ].join('\n');
}

/** What the node figures lack: a backend, a grid or a change. */
export function nodeProblems(n: NodeFigures): string[] {
  const problems: string[] = [];
  if (n.backends.map((f) => f.backend).join() !== NODE_BACKENDS.join())
    problems.push(`node figures of backends ${n.backends.map((f) => f.backend).join(', ')}, not ${NODE_BACKENDS.join(', ')}`);
  for (const f of n.backends) {
    if (f.changes.length !== changeSettings(n).length)
      problems.push(`node figures, ${f.backend}: option changes in ${f.changes.length} settings, not ${changeSettings(n).length}`);
    for (const c of f.changes)
      if (c.figures.length !== NODE_OPTION_CHANGES.length)
        problems.push(
          `node figures, ${f.backend}, ${settingLabel(c)}: ${c.figures.length} option changes, not ${NODE_OPTION_CHANGES.length}`,
        );
    const grids: readonly (readonly [string, readonly GridError[]])[] = [
      ...NODE_GRID_MODES.map((m) => [m, f.gridErrors[m]] as const),
      ['three.js', f.threeGridErrors],
    ];
    for (const [what, errors] of grids)
      if (errors.length !== 2) problems.push(`node figures, ${f.backend}, ${what}: ${errors.length} error grids, not 2`);
  }
  return problems;
}

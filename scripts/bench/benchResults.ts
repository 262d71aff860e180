/**
 * What a benchmark run writes (bench-results.json, or the smoke's file) and what docs/benchmarks.md
 * is generated from; and the check that every figure a run should have is there and finite.
 */
import type { BenchPlan } from './benchPlan.ts';
import type { BundleSizes } from './bundleSize.ts';
import type { DefaultViewFigures } from './defaultView.ts';
import type { DemoPageFigures } from './demoPage.ts';
import type { GpuSimulationSpeed, SimulationSpeed } from './flowSpeed.ts';
import type { MaterialFigures } from './materialFigures.ts';
import type { NodeFigures } from './nodeFigures.ts';
import type { PackageSize } from './packageSize.ts';
import type { ReferenceSpeed } from './referenceSpeed.ts';
import type { BenchRow } from './rows.ts';
import { nodeProblems } from './nodeMarkdown.ts';
import type { MeasuredRow } from './rowsMarkdown.ts';

export interface BenchResults {
  readonly plan: BenchPlan;
  /** the machine: Node's version, logical CPUs, their model, the 1-minute load average at the start and the end, the WebGL2 backend and its renderer */
  readonly machine: {
    readonly node: string;
    readonly cpus: number;
    readonly cpuModel: string;
    readonly load: readonly number[];
    readonly webgl: string;
  };
  readonly reference: ReferenceSpeed | null;
  readonly rows: readonly MeasuredRow[];
  /** the flowing film's simulation speed per grid of plan.flowSpeed, on the GPU and in the twin; null: not run (rows picked without it) or failed */
  readonly flowGpu: readonly GpuSimulationSpeed[] | null;
  readonly flowTwin: readonly SimulationSpeed[] | null;
  /** null: not run (rows picked without it) or failed */
  readonly materials: MaterialFigures | null;
  /** null: not run (rows picked without it) or failed */
  readonly node: NodeFigures | null;
  readonly bundle: BundleSizes | null;
  readonly package: PackageSize | null;
  readonly demo: DemoPageFigures | null;
  readonly defaultView: DefaultViewFigures | null;
  /** each stage's time, s */
  readonly stageSeconds: Readonly<Record<string, number>>;
  readonly seconds: number;
  /** the stages that threw, with why */
  readonly failures: readonly { readonly stage: string; readonly message: string }[];
}

/** The fields that may be null (not measured, or not applicable), or hold entries that may be. */
const NULLABLE = new Set(['tableBuildMs', 'errors', 'elementGzipBytes', 'frames', 'changeToFrameMs', 'gridN', 'turns', 'second']);

/**
 * Every number under `value` that is not finite, every undefined, and every null but in NULLABLE,
 * by its path: the same on the results in memory and read back from JSON (where NaN is null).
 */
function nonFinite(value: unknown, path: string, key: string, parentKey: string): string[] {
  if (value === undefined) return [`${path} is missing`];
  if (value === null) return NULLABLE.has(key) || NULLABLE.has(parentKey) ? [] : [`${path} is null`];
  if (typeof value === 'number') return Number.isFinite(value) ? [] : [`${path} is ${value}`];
  if (typeof value !== 'object') return [];
  return Object.entries(value).flatMap(([k, v]) => nonFinite(v, `${path}.${k}`, k, key));
}

/**
 * What is wrong with a run's results: a stage that threw, a figure that is not finite, or one that
 * is missing — a row without its first frame time, error columns where a row measures error and
 * none where it does not, a size or a change not timed but where the frame budget trims them.
 */
export function resultProblems(
  r: BenchResults,
  rowOf: (rowName: string) => Pick<BenchRow, 'kind' | 'measuresError' | 'timesChanges' | 'takesTurnsWith'>,
  expect: { readonly materials: boolean; readonly node: boolean; readonly flowSpeed: boolean },
): string[] {
  const problems = r.failures.map((f) => `${f.stage} threw: ${f.message}`);
  const figures = {
    reference: r.reference,
    rows: r.rows,
    flowGpu: r.flowGpu,
    flowTwin: r.flowTwin,
    materials: r.materials,
    node: r.node,
    bundle: r.bundle,
    package: r.package,
    demo: r.demo,
    defaultView: r.defaultView,
  };
  for (const [name, f] of Object.entries(figures)) if (f !== null) problems.push(...nonFinite(f, `results.${name}`, name, ''));
  for (const [name, figures] of Object.entries({
    reference: r.reference,
    bundle: r.bundle,
    package: r.package,
    demo: r.demo,
    defaultView: r.defaultView,
  }))
    if (figures === null) problems.push(`no ${name} figures`);
  if (expect.materials && r.materials === null) problems.push('no materials figures');
  if (expect.node && r.node === null) problems.push('no node figures (WebGPURenderer)');
  if (r.node) problems.push(...nodeProblems(r.node));
  if (r.plan.demo.panelTwice && r.demo?.panel.some((c) => c.programs.second === null))
    problems.push('a panel change not made a second time, though the plan makes each twice');
  if (expect.flowSpeed)
    for (const [name, speeds] of Object.entries({ 'flow GPU': r.flowGpu, 'flow twin': r.flowTwin })) {
      const grids = speeds?.map((s) => s.gridN) ?? [];
      if (r.plan.flowSpeed.grids.some((n) => !grids.includes(n))) problems.push(`no ${name} figures at every grid of the plan`);
    }
  for (const row of r.rows) {
    const { kind, measuresError, timesChanges, takesTurnsWith } = rowOf(row.name);
    if (row.frames[0] == null) problems.push(`${row.name}: no frame time at the first size`);
    if (takesTurnsWith !== undefined && row.turns?.frames[0] == null)
      problems.push(`${row.name}: no frame time of the view taking turns with it (${takesTurnsWith}) at the first size`);
    if (measuresError && row.errors === null) problems.push(`${row.name}: no error columns, though the row measures error`);
    if (!measuresError && row.errors !== null) problems.push(`${row.name}: error columns, though the row measures no error`);
    if (row.errors !== null && row.errors.length !== 2) problems.push(`${row.name}: ${row.errors.length} error grids, not 2`);
    // Trimmed by the budget: the sizes after a frame that outlasted it, and the changes of a row whose first did.
    const overBudget = row.frames.map((f) => f !== null && f.medianMs > r.plan.frameBudgetMs);
    row.frames.forEach((f, k) => {
      if (f === null && !overBudget.slice(0, k).includes(true)) problems.push(`${row.name}: size ${k + 1} not timed`);
    });
    const changesTrimmed = kind === 'textured' || timesChanges === false || overBudget[0] === true;
    if (!changesTrimmed && row.changeToFrameMs.some((c) => c === null)) problems.push(`${row.name}: a change not timed`);
  }
  return problems;
}

/**
 * One benchmark run: the reference's and the flow twin's speed in Node, the picked rows and the
 * flow's GPU simulation in headless Chromium (a Vite dev server), the material's figures, the
 * builds' sizes and the built demo page (vite preview).
 * A stage that throws is recorded and the run goes on; the caller reports it.
 */
import { cpus, loadavg } from 'node:os';
import { type Browser, chromium } from '@playwright/test';
import { createServer, preview } from 'vite';
import type { Medium } from '../../src/physics/medium.ts';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import { checkedRenderer, chromiumLaunchOptions } from '../chromium.ts';
import type { ParityGroup } from '../harness/parityCase.ts';
import { type BenchPlan, thinnedGrid } from './benchPlan.ts';
import type { BenchResults } from './benchResults.ts';
import { RowLane, gpuFlowSpeedInPage, warmUp } from './browserRows.ts';
import { type BundleSizes, buildAndMeasure } from './bundleSize.ts';
import { type DefaultViewFigures, defaultViewFigures } from './defaultView.ts';
import { type DemoPageFigures, demoPageFigures } from './demoPage.ts';
import { FIXED_GRID, STRESS_GRID, gridError, referenceXyz } from './errorGrids.ts';
import type { GpuSimulationSpeed } from './flowSpeed.ts';
import { type MaterialFigures, materialFigures } from './materialFigures.ts';
import { type NodeFigures, nodeFigures } from './nodeFigures.ts';
import { type PackageSize, packageSize } from './packageSize.ts';
import { Progress, type Stage, rowCost } from './progress.ts';
import { referenceSpeed } from './referenceSpeed.ts';
import { type BenchRow, FLOW_SPEED_ROW, MATERIALS_ROW, NODE_ROW } from './rows.ts';
import type { MeasuredRow } from './rowsMarkdown.ts';
import { type LaneTask, runAtOnce } from './runAtOnce.ts';
import { twinSpeed } from './twinSpeed.ts';

const REFERENCE_STAGE = 'reference speed';
const BUNDLE_STAGE = 'demo and element builds';
const PACKAGE_STAGE = 'package (npm pack)';
const DEMO_STAGE = 'built demo page';
const DEFAULT_VIEW_STAGE = 'built demo: its default view (the flow, governed) against the swirl';
const FLOW_TWIN_STAGE = `${FLOW_SPEED_ROW}: the twin in Node`;
const FLOW_GPU_STAGE = `${FLOW_SPEED_ROW}: the GPU`;

/** Expected costs of the stages other than the rows, against a fast row's (the full run). */
const STAGE_COSTS = { reference: 0.5, flowTwin: 1, flowGpu: 3, materials: 3, node: 4, bundle: 1.5, package: 1.5, demo: 5, defaultView: 3 };

/** The error grids of a film (the soap film, or a row's own index) and their reference colours, computed once per film. */
class ErrorGrids {
  private readonly byFilm = new Map<string, { grids: ParityGroup[]; reference: Xyz[][] | null }>();
  constructor(private readonly stride: number) {}

  private entry(nFilm: Medium) {
    const key = JSON.stringify(nFilm);
    const entry = this.byFilm.get(key) ?? {
      grids: [FIXED_GRID, STRESS_GRID].map((g) => thinnedGrid({ ...g, nFilm }, this.stride)),
      reference: null,
    };
    this.byFilm.set(key, entry);
    return entry;
  }

  grids(nFilm: Medium): ParityGroup[] {
    return this.entry(nFilm).grids;
  }

  reference(nFilm: Medium): Xyz[][] {
    const entry = this.entry(nFilm);
    entry.reference ??= entry.grids.map(referenceXyz);
    return entry.reference;
  }
}

/** A row measured: its figures, and its error columns exactly when it measures error. */
async function measureRow(lane: RowLane, row: BenchRow, grids: ErrorGrids): Promise<MeasuredRow> {
  const t0 = performance.now();
  const rowGrids = row.measuresError ? grids.grids(row.settings.nFilm) : [];
  const { xyz, ...result } = await lane.run(row, rowGrids);
  if (xyz.length !== rowGrids.length) throw new Error(`the page drew ${xyz.length} error grids, not ${rowGrids.length}`);
  const reference = row.measuresError ? grids.reference(row.settings.nFilm) : [];
  const errors = row.measuresError ? rowGrids.map((g, i) => gridError(g, reference[i]!, xyz[i]!)) : null;
  return { name: row.name, settings: row.settings, quality: row.quality, ...result, errors, seconds: (performance.now() - t0) / 1000 };
}

/** The stages that run with every row, or where picked by name. */
export interface BenchExtras {
  readonly materials: boolean;
  readonly node: boolean;
  readonly flowSpeed: boolean;
}

/** The run's stages in the order they start one by one, each with its expected cost. */
function benchStages(rows: readonly BenchRow[], extras: BenchExtras): Stage[] {
  return [
    { name: REFERENCE_STAGE, cost: STAGE_COSTS.reference },
    ...(extras.flowSpeed ? [{ name: FLOW_TWIN_STAGE, cost: STAGE_COSTS.flowTwin }] : []),
    ...rows.map((r) => ({ name: r.name, cost: rowCost(r) })),
    ...(extras.flowSpeed ? [{ name: FLOW_GPU_STAGE, cost: STAGE_COSTS.flowGpu }] : []),
    ...(extras.materials ? [{ name: MATERIALS_ROW, cost: STAGE_COSTS.materials }] : []),
    ...(extras.node ? [{ name: NODE_ROW, cost: STAGE_COSTS.node }] : []),
    { name: BUNDLE_STAGE, cost: STAGE_COSTS.bundle },
    { name: PACKAGE_STAGE, cost: STAGE_COSTS.package },
    { name: DEMO_STAGE, cost: STAGE_COSTS.demo },
    { name: DEFAULT_VIEW_STAGE, cost: STAGE_COSTS.defaultView },
  ];
}

/** Runs the run's stages, each timed and its progress printed; what a stage throws is recorded (null returned) and the run goes on. */
class StageRunner {
  readonly failures: { stage: string; message: string }[] = [];
  readonly stageSeconds: Record<string, number> = {};
  private readonly progress: Progress;

  constructor(private readonly stages: readonly Stage[]) {
    this.progress = new Progress(stages);
  }

  async run<T>(name: string, work: () => Promise<T> | T): Promise<T | null> {
    const index = this.stages.findIndex((s) => s.name === name);
    const t0 = performance.now();
    try {
      return await this.progress.run(index, work);
    } catch (error) {
      const message = error instanceof Error ? (error.stack ?? error.message) : String(error);
      console.error(`${name} threw: ${message}`);
      this.failures.push({ stage: name, message });
      return null;
    } finally {
      this.stageSeconds[name] = (performance.now() - t0) / 1000;
    }
  }
}

/** What the stages in the browser measure, each null until measured (or where its stage threw); the rows by index. */
interface BrowserFigures {
  rows: (MeasuredRow | null)[];
  materials: MaterialFigures | null;
  node: NodeFigures | null;
  flowGpu: GpuSimulationSpeed[] | null;
  bundle: BundleSizes | null;
  package: PackageSize | null;
  demo: DemoPageFigures | null;
  defaultView: DefaultViewFigures | null;
}

/** What the browser's stages share: where they run, and where they put what they measure. */
interface BrowserRun {
  readonly stages: StageRunner;
  readonly browser: Browser;
  readonly plan: BenchPlan;
  readonly devUrl: string;
  readonly grids: ErrorGrids;
  readonly figures: BrowserFigures;
}

/**
 * The builds, then the built demo page in a preview server of its own. The package is a task of
 * its own: its build (dist-lib) is not the demo's (dist).
 */
async function builtPage({ stages, browser, plan, figures }: BrowserRun): Promise<void> {
  figures.bundle = await stages.run(BUNDLE_STAGE, buildAndMeasure);
  const previewServer = await preview({ logLevel: 'silent', preview: { port: plan.previewPort, strictPort: true, host: '127.0.0.1' } });
  const previewUrl = `http://127.0.0.1:${plan.previewPort}`;
  try {
    figures.demo = await stages.run(DEMO_STAGE, () => demoPageFigures(browser, previewUrl, plan.demo));
    figures.defaultView = await stages.run(DEFAULT_VIEW_STAGE, () =>
      defaultViewFigures(() => chromium.launch(chromiumLaunchOptions()), previewUrl, plan.defaultView),
    );
  } finally {
    await new Promise((resolve) => previewServer.httpServer.close(resolve));
  }
}

/** The browser's stages as tasks, each with its expected cost; the rows run in the lane they are given. */
function browserTasks(run: BrowserRun, rows: readonly BenchRow[], extras: BenchExtras): LaneTask<RowLane>[] {
  const { stages, browser, plan, devUrl, grids, figures } = run;
  const flowGpu = async () => {
    figures.flowGpu = await stages.run(FLOW_GPU_STAGE, () => gpuFlowSpeedInPage(browser, devUrl, plan.flowSpeed));
  };
  const materials = async () => {
    // The material's film is three's iridescenceIOR, one number: the soap film's grids.
    figures.materials = await stages.run(MATERIALS_ROW, () =>
      materialFigures(browser, devUrl, plan.materials, grids.grids(FIXED_GRID.nFilm), grids.reference(FIXED_GRID.nFilm)),
    );
  };
  const node = async () => {
    figures.node = await stages.run(NODE_ROW, () =>
      nodeFigures(
        browser,
        devUrl,
        { ...plan.node, frameBudgetMs: plan.frameBudgetMs },
        grids.grids(FIXED_GRID.nFilm),
        grids.reference(FIXED_GRID.nFilm),
      ),
    );
  };
  const pack = async () => {
    figures.package = await stages.run(PACKAGE_STAGE, packageSize);
  };
  return [
    ...rows.map((row, i) => ({
      cost: rowCost(row),
      run: async (lane: RowLane) => {
        figures.rows[i] = await stages.run(row.name, () => measureRow(lane, row, grids));
      },
    })),
    ...(extras.flowSpeed ? [{ cost: STAGE_COSTS.flowGpu, run: flowGpu }] : []),
    ...(extras.materials ? [{ cost: STAGE_COSTS.materials, run: materials }] : []),
    ...(extras.node ? [{ cost: STAGE_COSTS.node, run: node }] : []),
    { cost: STAGE_COSTS.package, run: pack },
    { cost: STAGE_COSTS.bundle + STAGE_COSTS.demo + STAGE_COSTS.defaultView, run: () => builtPage(run) },
  ];
}

/**
 * The rows and the material in a dev server, and the built page: in this order one by one, or (the
 * smoke) the costliest first, `concurrency` at once, each lane's rows in its own page where the
 * plan keeps one per lane.
 */
async function browserFigures(
  stages: StageRunner,
  browser: Browser,
  plan: BenchPlan,
  rows: readonly BenchRow[],
  extras: BenchExtras,
): Promise<BrowserFigures> {
  const devUrl = `http://127.0.0.1:${plan.devPort}`;
  const run: BrowserRun = {
    stages,
    browser,
    plan,
    devUrl,
    grids: new ErrorGrids(plan.gridStride),
    figures: { rows: [], materials: null, node: null, flowGpu: null, bundle: null, package: null, demo: null, defaultView: null },
  };
  const server = await createServer({
    logLevel: 'silent',
    server: { port: plan.devPort, strictPort: true, host: '127.0.0.1', hmr: false, watch: null },
  });
  await server.listen();
  try {
    // Only where the first frames are figures: the smoke's times mean nothing.
    if (!plan.smoke) await warmUp(browser, devUrl);
    const lanes = Array.from({ length: plan.concurrency }, () => new RowLane(browser, devUrl, plan));
    try {
      await runAtOnce(browserTasks(run, rows, extras), lanes);
    } finally {
      await Promise.all(lanes.map((lane) => lane.close()));
    }
  } finally {
    await server.close();
  }
  return run.figures;
}

export async function runBench(plan: BenchPlan, rows: readonly BenchRow[], extras: BenchExtras): Promise<BenchResults> {
  const started = performance.now();
  const load = [loadavg()[0]!];
  const stages = new StageRunner(benchStages(rows, extras));
  const reference = await stages.run(REFERENCE_STAGE, referenceSpeed);
  // In Node, before the browser: the twin's steps hold the process, which drives the pages.
  const flowTwin = extras.flowSpeed ? await stages.run(FLOW_TWIN_STAGE, () => twinSpeed(plan.flowSpeed)) : null;
  const browser = await chromium.launch(chromiumLaunchOptions());
  try {
    const webgl = await checkedRenderer(browser);
    console.error(webgl);
    const figures = await browserFigures(stages, browser, plan, rows, extras);
    load.push(loadavg()[0]!);
    return {
      plan,
      machine: { node: process.version, cpus: cpus().length, cpuModel: cpus()[0]?.model ?? 'unknown', load, webgl },
      reference,
      rows: figures.rows.filter((m) => m !== null),
      flowGpu: figures.flowGpu,
      flowTwin,
      materials: figures.materials,
      node: figures.node,
      bundle: figures.bundle,
      package: figures.package,
      demo: figures.demo,
      defaultView: figures.defaultView,
      stageSeconds: stages.stageSeconds,
      seconds: (performance.now() - started) / 1000,
      failures: stages.failures,
    };
  } finally {
    await browser.close();
  }
}

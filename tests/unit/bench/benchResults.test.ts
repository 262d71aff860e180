/** The check a benchmark run ends with: a stage that threw, a figure missing or not finite. */
import { describe, expect, it } from 'vitest';
import { FULL_PLAN, SMOKE_PLAN } from '../../../scripts/bench/benchPlan.ts';
import type { BenchResults } from '../../../scripts/bench/benchResults.ts';
import { resultProblems } from '../../../scripts/bench/benchResults.ts';
import type { NodeBackendFigures } from '../../../scripts/bench/nodeFigures.ts';
import { NODE_OPTION_CHANGES } from '../../../scripts/bench/nodeMaterials.ts';
import type { MeasuredRow } from '../../../scripts/bench/rowsMarkdown.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';

const stats = { cases: 100, max: 0.1, p99: 0.08, mean: 0.02, worst: { thicknessNm: 10, angleDeg: 5 } };
const row = (name: string, more: Partial<MeasuredRow> = {}): MeasuredRow => ({
  // the floor shows no film: its changes are not timed
  name,
  settings: DEFAULT_SETTINGS,
  quality: DEFAULT_FILM_QUALITY,
  firstFrameMs: 900,
  tableBuildMs: 300,
  rebuildsWhileAnimating: 0,
  frames: [{ medianMs: 60, count: 30 }],
  changeToFrameMs: name === 'floor' ? [null, null, null, null] : [300, 310, 320, 330],
  turns: null,
  errors: null,
  seconds: 12,
  ...more,
});
const results = (rows: MeasuredRow[], more: Partial<BenchResults> = {}): BenchResults => ({
  plan: FULL_PLAN,
  machine: { node: 'v20', cpus: 2, cpuModel: 'cpu', load: [1, 1], webgl: 'WebGL2 backend llvmpipe: llvmpipe' },
  reference: {
    reflectancePerSecondSharedOptics: 1e7,
    reflectancePerSecondFullCall: 5e5,
    table0to2000nmAt1nmMs: 99,
    thickestFilmColorMs: 1,
    sink: 3,
  },
  rows,
  flowGpu: null,
  flowTwin: null,
  materials: null,
  node: null,
  bundle: { files: {}, demoGzipBytes: 1000, elementGzipBytes: 900, environmentGzipBytes: [100] },
  package: { tarballBytes: 100, unpackedBytes: 300, files: 5 },
  demo: null,
  defaultView: null,
  stageSeconds: {},
  seconds: 600,
  failures: [],
  ...more,
});
const measures = (name: string) => ({
  kind: name === 'floor' ? ('textured' as const) : ('bubble' as const),
  measuresError: name !== 'floor',
});

/** A run of rows picked without the materials, the node figures and the flow speed. */
const NONE = { materials: false, node: false, flowSpeed: false } as const;

describe('bench results check', () => {
  const good = [row('floor'), row('table', { errors: [stats, stats] })];

  it('a complete run has no problems but the figures it lacks', () => {
    expect(resultProblems(results(good), measures, NONE)).toEqual(['no demo figures', 'no defaultView figures']);
  });

  it('names a figure that is not finite, by its path', () => {
    const bad = [good[0]!, row('table', { errors: [stats, stats], frames: [{ medianMs: NaN, count: 30 }] })];
    expect(resultProblems(results(bad), measures, NONE)).toContain('results.rows.1.frames.0.medianMs is NaN');
  });

  it('finds it again in the results read back from JSON (where NaN is null), and accepts the nulls that mean not measured', () => {
    const bad = [good[0]!, row('table', { errors: [stats, stats], frames: [{ medianMs: NaN, count: 30 }] })];
    const readBack = JSON.parse(JSON.stringify(results(bad))) as BenchResults;
    expect(resultProblems(readBack, measures, NONE)).toEqual([
      'results.rows.1.frames.0.medianMs is null',
      'no demo figures',
      'no defaultView figures',
    ]);
    expect(resultProblems(JSON.parse(JSON.stringify(results(good))) as BenchResults, measures, NONE)).toEqual([
      'no demo figures',
      'no defaultView figures',
    ]);
  });

  it("a row taking turns with an earlier model has that view's frame time at the first size, finite", () => {
    const turnsOf = (name: string) => ({
      ...measures(name),
      ...(name === 'matrix' && { measuresError: false, takesTurnsWith: 'rgbProduct' as const }),
    });
    const turns = { model: 'rgbProduct' as const, frames: [{ medianMs: 50, count: 20 }] };
    expect(resultProblems(results([...good, row('matrix', { turns })]), turnsOf, NONE)).toEqual([
      'no demo figures',
      'no defaultView figures',
    ]);
    expect(resultProblems(results([...good, row('matrix')]), turnsOf, NONE)).toContain(
      'matrix: no frame time of the view taking turns with it (rgbProduct) at the first size',
    );
    const nan = { ...turns, frames: [{ medianMs: NaN, count: 20 }] };
    expect(resultProblems(results([...good, row('matrix', { turns: nan })]), turnsOf, NONE)).toContain(
      'results.rows.2.turns.frames.0.medianMs is NaN',
    );
  });

  it('each panel change made a second time where the plan makes it twice (the full run), once in the smoke', () => {
    const change = (second: number | null) => ({
      programs: { first: 1, back: 0, second },
      longTasks: { count: 0, maxMs: 0 },
      texels: 100,
      fullMs: 500,
    });
    const counts = { frames: 60, tableBuilds: 0 };
    const demo = (second: number | null) => ({
      firstFrameMs: 900,
      firstCompleteFrameMs: 1000,
      still: counts,
      animating: counts,
      canvasHidden: counts,
      pageHidden: counts,
      panel: [change(0), change(second)],
      parallelCompile: true,
    });
    const twice = 'a panel change not made a second time, though the plan makes each twice';
    expect(resultProblems(results(good, { demo: demo(null) }), measures, NONE)).toContain(twice);
    expect(resultProblems(results(good, { demo: demo(0) }), measures, NONE)).not.toContain(twice);
    expect(resultProblems(results(good, { plan: SMOKE_PLAN, demo: demo(null) }), measures, NONE)).toEqual(['no defaultView figures']);
  });

  it('error columns exist exactly where a row measures error', () => {
    const problems = resultProblems(results([row('floor', { errors: [stats, stats] }), row('table')]), measures, NONE);
    expect(problems).toContain('floor: error columns, though the row measures no error');
    expect(problems).toContain('table: no error columns, though the row measures error');
  });

  it('the flow speed figures at every grid of the plan, each finite', () => {
    const speed = (gridN: number, stepsPerSecond = 10) => ({ gridN, stepSeconds: 0.004, stepsPerSecond, filmSecondsPerSecond: 0.04 });
    const all = FULL_PLAN.flowSpeed.grids;
    const r = results(good, {
      flowGpu: all.map((n) => ({ ...speed(n), drawsPerStep: 103 })),
      flowTwin: [speed(all[0]!, NaN)],
    });
    expect(resultProblems(r, measures, { materials: false, node: false, flowSpeed: true })).toEqual([
      'results.flowTwin.0.stepsPerSecond is NaN',
      'no demo figures',
      'no defaultView figures',
      'no flow twin figures at every grid of the plan',
    ]);
    // Not asked for (rows picked without it): none is missing.
    expect(resultProblems(results(good), measures, NONE)).toEqual(['no demo figures', 'no defaultView figures']);
  });

  it('a stage that threw, missing materials, a size or a change not timed where the budget does not trim them', () => {
    const untimed = row('table', {
      errors: [stats, stats],
      frames: [{ medianMs: 60, count: 20 }, null],
      changeToFrameMs: [300, null, 320, 330],
    });
    const r = results([good[0]!, untimed], { plan: SMOKE_PLAN, failures: [{ stage: 'exact, 90 bins', message: 'lost context' }] });
    expect(resultProblems(r, measures, { materials: true, node: true, flowSpeed: true })).toEqual(
      expect.arrayContaining([
        'exact, 90 bins threw: lost context',
        'no materials figures',
        'no node figures (WebGPURenderer)',
        'no flow GPU figures at every grid of the plan',
        'table: size 2 not timed',
        'table: a change not timed',
      ]),
    );
  });

  it('a row whose frame outlasts the budget is trimmed (its larger sizes and its changes), not incomplete', () => {
    const slow = row('exact', {
      errors: [stats, stats],
      frames: [{ medianMs: FULL_PLAN.frameBudgetMs + 1, count: 1 }, null],
      changeToFrameMs: [null, null, null, null],
    });
    expect(resultProblems(results([good[0]!, slow]), measures, NONE)).toEqual(['no demo figures', 'no defaultView figures']);
  });

  it('the node figures of both backends in order, each with every option change and both error grids per mode, each finite', () => {
    const change = { longestMs: 0, longestThreadMs: 0, mostThreadMs: 0, over: 0, toFrameMs: 40 };
    const t = (medianMs: number) => ({ medianMs, count: 1 });
    const backend = (name: 'webgl' | 'webgpu'): NodeBackendFigures => ({
      backend: name,
      frames: { floor: t(10), 'three.js': t(12), table: t(13), exact: t(40) },
      gridErrors: { table: [stats, stats], exact: [stats, stats] },
      threeGridErrors: [stats, stats],
      changes: [{ width: 160, height: 90, gpuApart: false, figures: NODE_OPTION_CHANGES.map(() => change) }],
    });
    const node = { ...SMOKE_PLAN.node, backends: [backend('webgl'), backend('webgpu')] };
    const ASKED = { ...NONE, node: true };
    expect(resultProblems(results(good, { node }), measures, ASKED)).toEqual(['no demo figures', 'no defaultView figures']);
    const lacking = {
      ...node,
      changesAlsoAt: [{ width: 160, height: 90, gpuApart: true }],
      backends: [
        { ...backend('webgl'), changes: [...backend('webgl').changes, { width: 160, height: 90, gpuApart: true, figures: [change] }] },
        { ...backend('webgpu'), gridErrors: { table: [stats], exact: [stats, stats] } },
      ],
    };
    expect(resultProblems(results(good, { node: lacking }), measures, ASKED)).toEqual(
      expect.arrayContaining([
        `node figures, webgl, 160×90, GPU process apart: 1 option changes, not ${NODE_OPTION_CHANGES.length}`,
        'node figures, webgpu, table: 1 error grids, not 2',
        'node figures, webgpu: option changes in 1 settings, not 2',
      ]),
    );
    const oneBackend = { ...node, backends: [{ ...backend('webgl'), frames: { ...backend('webgl').frames, exact: t(NaN) } }] };
    expect(resultProblems(results(good, { node: oneBackend }), measures, ASKED)).toEqual(
      expect.arrayContaining(['results.node.backends.0.frames.exact.medianMs is NaN', 'node figures of backends webgl, not webgl, webgpu']),
    );
  });
});

/**
 * How fast the flowing film is simulated: whole steps per wall second of the GPU port
 * (GpuFilmSimulation on the benchmark page's renderer) and of the float64 twin (in Node), at a
 * few grids, with the GPU's draws per step; the median of timed batches after untimed steps.
 * The timing and the Markdown; the page (page/gpuFlowSpeed.ts) and Node (twinSpeed.ts) run it.
 */
import { median } from './median.ts';

/** What the flow's speed figures measure: the grids (cells per cube face side), the untimed steps first, then `batches` timed batches of `batchSteps` steps each. */
export interface FlowSpeedPlan {
  readonly grids: readonly number[];
  readonly warmUpSteps: number;
  readonly batchSteps: number;
  readonly batches: number;
}

/**
 * The film timed, on the GPU and in the twin alike: flowTwin.ts's seeded film in a gentle wind, so
 * every pass has work; Δt is the defaults' (the wind is slower than the free drainage speed).
 */
export const SPEED_FILM = { seed: 1, windMps: 0.05 } as const;

/** One simulation's speed at one grid. */
export interface SimulationSpeed {
  readonly gridN: number;
  /** Δt, film seconds */
  readonly stepSeconds: number;
  /** the median over the batches of their steps per wall second */
  readonly stepsPerSecond: number;
  readonly filmSecondsPerSecond: number;
}

export interface GpuSimulationSpeed extends SimulationSpeed {
  /** draws of one step, counted by the renderer (renderer.info.render.calls) */
  readonly drawsPerStep: number;
}

/**
 * Steps per wall second: `step(k)` runs k steps, `sync()` waits until the steps asked are done (a
 * GPU's 1-pixel read-back; nothing for the twin). The plan's untimed steps first (the programs'
 * compile, the caches), then the median of its timed batches.
 */
export function timedStepsPerSecond(plan: FlowSpeedPlan, step: (count: number) => void, sync: () => void): number {
  step(plan.warmUpSteps);
  sync();
  const rates = Array.from({ length: plan.batches }, () => {
    const started = performance.now();
    step(plan.batchSteps);
    sync();
    return plan.batchSteps / ((performance.now() - started) / 1000);
  });
  return median(rates);
}

/** A simulation's figures from its step and its rate. */
export const simulationSpeed = (gridN: number, stepSeconds: number, stepsPerSecond: number): SimulationSpeed => ({
  gridN,
  stepSeconds,
  stepsPerSecond,
  filmSecondsPerSecond: stepsPerSecond * stepSeconds,
});

/** The figures as a table, the twin's beside the GPU's at each grid either measured. */
export function flowSpeedMarkdown(
  gpu: readonly GpuSimulationSpeed[] | null,
  twin: readonly SimulationSpeed[] | null,
  plan: FlowSpeedPlan,
): string {
  const at = <T extends SimulationSpeed>(list: readonly T[] | null, n: number) => list?.find((s) => s.gridN === n);
  const rate = (s: SimulationSpeed | undefined) =>
    s ? `${s.stepsPerSecond.toPrecision(3)} / ${s.filmSecondsPerSecond.toPrecision(2)}` : 'not measured';
  const lines = plan.grids.map((n) => {
    const g = at(gpu, n);
    const t = at(twin, n);
    const step = g ?? t;
    return `| ${n}² (6×${n}² cells) | ${step ? `${(step.stepSeconds * 1e3).toPrecision(3)} ms` : '—'} | ${rate(g)} | ${g ? g.drawsPerStep : '—'} | ${rate(t)} |`;
  });
  return [
    '| flowing film, cells per face | Δt (film time) | GPU: steps/s / film s per s | GPU: draws per step | float64 twin (Node): steps/s / film s per s |',
    '|---|---|---|---|---|',
    ...lines,
    '',
    `Steps per wall second: the median of ${plan.batches} batch${plan.batches === 1 ? '' : 'es'} of ${plan.batchSteps} step${plan.batchSteps === 1 ? '' : 's'}, after ${plan.warmUpSteps} untimed, of a film seeded ${SPEED_FILM.seed} in a ${SPEED_FILM.windMps} m/s wind, every other parameter at its default. GPU: a GpuFilmSimulation on the benchmark page's renderer (headless Chromium's WebGL2), each batch synced by a 1-pixel read-back of the film target; its draws per step counted by three's renderer.info (render.calls) around one step, to set beside the passes per step of docs/flow.md's cost table. Twin: src/physics/filmDynamics's stepFilm in Node, in the bench's own process (\`npm run bench:flow\` prints more of it). Film s per s: steps per second × Δt, 1 where the film keeps real time.`,
  ].join('\n');
}

declare global {
  interface Window {
    benchFlowSpeed?: (plan: FlowSpeedPlan) => GpuSimulationSpeed[];
  }
}

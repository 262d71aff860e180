/**
 * What the flowing film's simulation costs the GPU (docs/flow.md#what-a-step-costs), counted
 * from the code that draws it: the view's FlowFieldState advances a GpuFilmSimulation frame by
 * frame as the app does, into a renderer that records each draw (its pass, by the call of
 * flowPasses.ts's PASSES its shader makes, and the size of the target it fills), so the passes,
 * their order, the steps per frame and the targets' sizes are the code's own. A pass's fetches
 * per fragment are counted from its material's GLSL with its defines and uniforms
 * (textureFetches.ts). `npm run docs` writes the tables between docs/flow.md's markers; a unit test
 * checks the file holds exactly them. Under `npm run docs` this module runs in Vite's module runner,
 * as the shaders' text comes through Vite's `import.meta.glob` (src/gpu/shaderSource.ts).
 */
import type { Color, Mesh, ShaderMaterial, WebGLRenderTarget, WebGLRenderer } from 'three';
import { FLOW_PARAMETERS } from '../../src/physics/filmDynamics/flowParameters.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { DEFAULT_FILM_QUALITY } from '../../src/settings/filmQuality.ts';
import type { FieldSettings } from '../../src/fields/fields.ts';
import type { FieldUniforms } from '../../src/fields/thicknessField.ts';
import { flowParametersOf } from '../../src/fields/flowField.ts';
import { FlowFieldState } from '../../src/gpuFilmDynamics/flowFieldState.ts';
import { GpuFilmSimulation } from '../../src/gpuFilmDynamics/gpuFilmSimulation.ts';
import { PASSES, type PassName } from '../../src/gpuFilmDynamics/flowPasses.ts';
import { loopNames, textureFetchesPerFragment } from './textureFetches.ts';

/** The grids of the table, beside the default. */
export const COST_GRIDS = [16, 32, 64, 128, 256] as const;

/** The display rate the frames are drawn at (an assumption of the table, not the code's): a common monitor's. */
export const DISPLAY_HZ = 60;

/** Frames counted: one second of them, after the frame that starts the film. */
const FRAMES = DISPLAY_HZ;

/**
 * The integrated GPU the frame time is estimated for, with its published peak rates: Intel Iris Xe
 * Graphics G7 96EU (Tiger Lake GT2; 24 ROPs and 48 texture units at a 1.1 GHz boost clock), as
 * TechPowerUp's GPU database lists it.
 */
export const ESTIMATE_GPU = {
  name: 'Intel Iris Xe Graphics G7 96EU',
  pixelsPerSecond: 24 * 1.1e9,
  texelsPerSecond: 48 * 1.1e9,
  source: 'https://www.techpowerup.com/gpu-specs/ (Intel Iris Xe Graphics G7 96EU)',
} as const;

/**
 * The loops counted once per call (textureFetches.ts): tfcMarkedCell's scan of a row's n cells
 * runs only for the row that holds the m-th marked cell (it is reached when m is below the row's
 * count of marks, and returns at that mark), not for each of the 6n rows around it.
 */
export const LOOPS_RUN_ONCE: ReadonlySet<string> = new Set(['tfcMarkedCell:i']);

/** One draw: its pass and the texels it fills. */
interface Draw {
  readonly pass: PassName;
  readonly fragments: number;
  readonly material: ShaderMaterial;
}

/** The pass whose material this is: the one whose texel call its main writes. */
function passOf(material: ShaderMaterial): PassName {
  const found = Object.entries(PASSES).find(([, [, texel]]) => material.fragmentShader.includes(`gl_FragColor = ${texel};`));
  if (!found) throw new Error('a draw with a material of no pass of PASSES');
  return found[0] as PassName;
}

/** A renderer that draws nothing and records what it is asked to draw, into which target. */
class RecordingRenderer {
  draws: Draw[] = [];
  private target: WebGLRenderTarget | null = null;
  getRenderTarget = (): WebGLRenderTarget | null => this.target;
  setRenderTarget = (target: WebGLRenderTarget | null): void => {
    this.target = target;
  };
  render = (mesh: Mesh): void => {
    if (!this.target) throw new Error('a flow pass drawn into the canvas');
    const material = mesh.material as ShaderMaterial;
    this.draws.push({ pass: passOf(material), fragments: this.target.width * this.target.height, material });
  };
  getClearColor = (color: Color): Color => color;
  getClearAlpha = (): number => 1;
  setClearColor = (): void => {};
  clear = (): void => {};
}

/** A pass's fetches per fragment: its GLSL with its defines, the loop bounds' uniforms at their values. */
function fetchesPerFragment(material: ShaderMaterial): number {
  const values = Object.fromEntries(
    Object.entries(material.uniforms).flatMap(([name, u]) => (typeof u.value === 'number' ? [[name, u.value]] : [])),
  );
  return textureFetchesPerFragment(material.fragmentShader, material.defines, {
    values,
    oncePerCall: LOOPS_RUN_ONCE,
  });
}

/** Draws, fragments and texture fetches of a run of draws. */
export interface Work {
  readonly draws: number;
  readonly fragments: number;
  readonly fetches: number;
}

/** One pass as a step draws it at a grid: its draws, the texels of each and the fetches per fragment. */
export interface PassCost {
  readonly pass: PassName;
  readonly draws: number;
  readonly fragmentsPerDraw: number;
  readonly fetchesPerFragment: number;
}

export interface GridCost {
  readonly n: number;
  readonly step: Work;
  readonly frame: Work;
  readonly stepsPerFrame: number;
  /** The steps a frame would take to keep the film at real time × simSpeed (the app's frames take at most flowStepsPerFrame). */
  readonly realTimeStepsPerFrame: number;
  readonly passes: readonly PassCost[];
}

function workOf(draws: readonly Draw[], fetches: (d: Draw) => number): Work {
  return {
    draws: draws.length,
    fragments: draws.reduce((sum, d) => sum + d.fragments, 0),
    fetches: draws.reduce((sum, d) => sum + d.fragments * fetches(d), 0),
  };
}

/** The simulation at grid n, its other parameters at their defaults, over FRAMES frames of the app and one step. */
export function gridCost(n: number): GridCost {
  const renderer = new RecordingRenderer();
  const state = new FlowFieldState(renderer as unknown as WebGLRenderer);
  const uniforms: FieldUniforms = { uFlowFilm: { value: null }, uFlowGridN: { value: 0 } };
  const settingsAt = (frame: number): FieldSettings => ({ ...DEFAULT_SETTINGS, gridN: n, timeSeconds: frame / DISPLAY_HZ });
  const budget = DEFAULT_FILM_QUALITY.flowStepsPerFrame;
  // Made by a frame that must show its time: its steps are not held for programs compiled in parallel.
  // The flow's parameters, as a frame derives them (the time is not one of them).
  const parameters = flowParametersOf(settingsAt(0));
  state.advance(uniforms, settingsAt(0), parameters, Infinity);
  renderer.draws = [];
  for (let frame = 1; frame <= FRAMES; frame++) state.advance(uniforms, settingsAt(frame), parameters, budget);
  const frameDraws = renderer.draws;
  const steps = state.steps;
  state.dispose();
  // One step of a simulation of the same film that has stepped before (its first step's programs made).
  renderer.draws = [];
  const sim = new GpuFilmSimulation(renderer as unknown as WebGLRenderer, parameters);
  sim.step(1);
  renderer.draws = [];
  sim.step(1);
  const stepDraws = renderer.draws;
  sim.dispose();

  const loops = new Set(stepDraws.flatMap((d) => loopNames(d.material.fragmentShader, d.material.defines)));
  for (const loop of LOOPS_RUN_ONCE) if (!loops.has(loop)) throw new Error(`LOOPS_RUN_ONCE names ${loop}, a loop of no pass`);
  const perFragment = new Map<ShaderMaterial, number>();
  const fetches = (d: Draw): number => {
    if (!perFragment.has(d.material)) perFragment.set(d.material, fetchesPerFragment(d.material));
    return perFragment.get(d.material)!;
  };
  const frame = workOf(frameDraws, fetches);
  const passes = new Map<PassName, PassCost>();
  for (const d of stepDraws) {
    const known = passes.get(d.pass);
    if (known && (known.fragmentsPerDraw !== d.fragments || known.fetchesPerFragment !== fetches(d))) {
      throw new Error(`${d.pass} is drawn at two sizes in a step: list its draws apart`);
    }
    passes.set(d.pass, { pass: d.pass, draws: (known?.draws ?? 0) + 1, fragmentsPerDraw: d.fragments, fetchesPerFragment: fetches(d) });
  }
  return {
    n,
    step: workOf(stepDraws, fetches),
    frame: { draws: frame.draws / FRAMES, fragments: frame.fragments / FRAMES, fetches: frame.fetches / FRAMES },
    stepsPerFrame: steps / FRAMES,
    realTimeStepsPerFrame: settingsAt(1).simSpeed / DISPLAY_HZ / sim.stepSeconds,
    passes: [...passes.values()],
  };
}

/** The estimated GPU time of some work, in ms: fragments at the fill rate or fetches at the texture rate, the longer. */
export const estimatedMs = (w: Work): number =>
  1000 * Math.max(w.fragments / ESTIMATE_GPU.pixelsPerSecond, w.fetches / ESTIMATE_GPU.texelsPerSecond);

export const DEFAULT_GRID_N = FLOW_PARAMETERS.find((r) => r.key === 'gridN')!.defaultValue;

const count = (x: number): string => Math.round(x).toLocaleString('en-US');
const millis = (x: number): string => (x < 10 ? x.toPrecision(2) : x.toFixed(0));

/** The table by grid and the default grid's passes, as Markdown. */
export function flowCostMarkdown(): string {
  const grids = [...new Set([...COST_GRIDS, DEFAULT_GRID_N])].sort((a, b) => a - b).map(gridCost);
  const rows = grids.map((g) =>
    [
      g.n === DEFAULT_GRID_N ? `**${g.n}** (default)` : `${g.n}`,
      count(g.step.draws),
      count(g.step.fragments),
      count(g.step.fetches),
      `${Number(g.stepsPerFrame.toFixed(2))} (${g.realTimeStepsPerFrame.toFixed(1)})`,
      count(g.frame.draws),
      count(g.frame.fragments),
      count(g.frame.fetches),
      `${millis(estimatedMs(g.step))} / ${millis(estimatedMs(g.frame))}`,
    ].join(' | '),
  );
  const byGrid = [
    `| N | passes per step | fragments per step | fetches per step | steps per frame (real time asks) | passes per frame | fragments per frame | fetches per frame | estimate on ${ESTIMATE_GPU.name}, ms per step / per frame |`,
    '|---|---|---|---|---|---|---|---|---|',
    ...rows.map((r) => `| ${r} |`),
  ];
  const standard = grids.find((g) => g.n === DEFAULT_GRID_N)!;
  const passes = [
    `| pass (N = ${DEFAULT_GRID_N}) | draws per step | texels per draw | fetches per fragment | share of a step's fetches |`,
    '|---|---|---|---|---|',
    ...standard.passes.map(
      (p) =>
        `| \`${p.pass}\` | ${p.draws} | ${count(p.fragmentsPerDraw)} | ${p.fetchesPerFragment} | ${((100 * p.draws * p.fragmentsPerDraw * p.fetchesPerFragment) / standard.step.fetches).toFixed(1)}% |`,
    ),
  ];
  return [...byGrid, '', ...passes].join('\n');
}

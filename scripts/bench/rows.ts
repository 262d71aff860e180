/**
 * The benchmark's rows: every method and setting worth comparing, the two that are not ours
 * (three.js's iridescence, a plain textured sphere), and the before/after of each way the cost
 * follows the scene. Every row draws the demo's default view (swirl, both walls, sky, sRGB)
 * unless its settings say otherwise.
 */
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { type FilmSettings, HDR_ENVIRONMENTS } from '../../src/settings/filmSettings.ts';
import type { FilmTableLayout } from '../../src/settings/filmTableLayout.ts';
import type { FilmLayer } from '../../src/physics/stackFilms.ts';
import { cubeSphereGrid } from '../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { flowNumbers } from '../../src/physics/filmDynamics/flowNumbers.ts';
import { validateFlowParameters } from '../../src/physics/filmDynamics/flowParameters.ts';
import { timeStep } from '../../src/physics/filmDynamics/timeStep.ts';
import type { EarlierModel } from './benchRow.ts';

export interface BenchRow {
  readonly name: string;
  readonly kind: 'bubble' | 'textured';
  /** an earlier model of the bubble's light (BenchRowSpec) */
  readonly earlierModel?: EarlierModel;
  /** an earlier model whose frames take turns with the row's (BenchRowSpec) */
  readonly takesTurnsWith?: EarlierModel;
  /** false: its changes are not timed (a row that changes only the scene around the default table, whose changes that row times) */
  readonly timesChanges?: false;
  readonly settings: FilmSettings;
  readonly quality: FilmQuality;
  /** whether the error columns apply (the film colour is ours or the peer's) */
  readonly measuresError: boolean;
  /**
   * false: left out of the smoke run, a costlier variant of a row it keeps (the same page and
   * figures, a slower shader that the browser tests draw): the smoke shows each kind of row runs
   */
  readonly smoke?: false;
}

const q = DEFAULT_FILM_QUALITY;
const view = (mode: FilmSettings['mode'], more: Partial<FilmSettings> = {}) => ({ ...DEFAULT_SETTINGS, mode, ...more });
const exact = (bins: number, tails: 'skipped' | 'kept' = 'skipped'): BenchRow => ({
  name: `exact, ${bins} bins${tails === 'kept' ? ', tails kept (before)' : ''}`,
  kind: 'bubble',
  settings: view('exact'),
  quality: { ...q, exactSpectralBins: bins, spectralTailTolerance: tails === 'kept' ? 0 : q.spectralTailTolerance },
  measuresError: true,
});
const layoutName = (l: FilmTableLayout) =>
  `${l.width === q.table.width && l.thickEndCellNm === q.table.thickEndCellNm ? `≤ ${l.width} (${l.thickEndCellNm} nm cells at the thick end)` : l.width}×${l.rows}×2, ${l.fill === 'series' ? 'Airy series' : `${l.spectralBins} bins`}, ${l.thicknessPower === 1 ? 'linear d' : `d ∝ u^${l.thicknessPower}`}, ${l.cosPower === 1 ? 'linear cos θ' : `cos θ ∝ v^${l.cosPower}`}`;
const table = (l: Partial<FilmTableLayout>, note = '', precision: FilmQuality['tablePrecision'] = 'auto'): BenchRow => {
  const layout = { ...q.table, ...l };
  return {
    name: `table ${layoutName(layout)}${precision === 'half' ? ', half float' : ''}${note}`,
    kind: 'bubble',
    settings: view('table'),
    quality: { ...q, table: layout, tablePrecision: precision },
    measuresError: true,
  };
};
const fourier = (maxOrders: number = q.airySeriesMaxOrders, note = ''): BenchRow => ({
  name: `fourier, Airy series per fragment, ${maxOrders === q.airySeriesMaxOrders ? 'every order (tail bound 1e-5)' : `m ≤ ${maxOrders}`}${note}`,
  kind: 'bubble',
  settings: view('fourier'),
  quality: { ...q, airySeriesMaxOrders: maxOrders },
  measuresError: true,
});
/** A step of the scene around the default table; its changes are timed only where its table is not the default row's. */
const sceneStep = (name: string, more: Partial<FilmSettings>, ownTable = false): BenchRow => ({
  name,
  kind: 'bubble',
  settings: view('table', more),
  quality: q,
  measuresError: false,
  ...(ownTable ? {} : { timesChanges: false as const }),
});

/** The display rate whose frames the flow rows draw: the page's frames advance the film time by 1/60 s each. */
const FRAME_HZ = 60;
/** The flow rows' grids (cells per cube face side). */
const FLOW_ROW_GRIDS = [32, 64, 128] as const;

/**
 * The flowing film at a fixed grid, drawn as the app draws it while animating: each frame advances
 * the film time by 1/60 s at simSpeed 1, so it takes the whole steps Δt that real time asks (the
 * mean below; a frame takes the whole number below or above it), under the app's flowStepsPerFrame
 * at these grids. Δt is the twin's rule for the grid, every other parameter at its default.
 */
function flowRow(gridN: number): BenchRow {
  const parameters = validateFlowParameters({ gridN });
  const numbers = flowNumbers(parameters);
  const stepMs = timeStep(cubeSphereGrid(gridN), numbers) * numbers.timeScaleS * 1e3;
  const stepsPerFrame = 1000 / FRAME_HZ / stepMs;
  return sceneStep(
    `default table, flow field, grid ${gridN} (6×${gridN}² cells; simSpeed 1, real time: a ${FRAME_HZ} Hz frame takes ${stepsPerFrame.toFixed(1)} steps of ${stepMs.toPrecision(3)} ms film time)`,
    { field: 'flow', gridN, simSpeed: 1 },
  );
}

/** 16-layer stacks of films: a TiO₂/SiO₂-like Bragg mirror of fixed layers on glass, and a nacre-like stack whose 1.68 layers follow the field. */
const stack16 = (layers: readonly FilmLayer[]): FilmLayer[] => Array.from({ length: 8 }, () => layers).flat();
const BRAGG_16 = {
  layers: stack16([
    { n: 2.35, thicknessNm: 56.6 },
    { n: 1.46, thicknessNm: 91.1 },
  ]),
  nInside: 1.52,
};
const NACRE_16 = {
  layers: stack16([
    { n: 1.68, thicknessNm: 'd' },
    { n: 1.43, thicknessNm: 30 },
  ]),
  nInside: 1.53,
};

/** The rows the README's table of accuracy against cost quotes: each method at its default, and three.js's. */
export const THREE_IRIDESCENCE_ROW: BenchRow = {
  name: 'three.js iridescence (evalIridescence, soap film)',
  kind: 'bubble',
  settings: view('three-iridescence'),
  quality: q,
  measuresError: true,
};
export const DEFAULT_TABLE_ROW = table({}, ' (default)');
export const FOURIER_ROW = fourier();
export const EXACT_ROW = exact(90);

export const ROWS: readonly BenchRow[] = [
  { name: 'plain textured sphere (the floor)', kind: 'textured', settings: view('table'), quality: q, measuresError: false },
  // The floor without the sky behind it: the background's own cost, to tell it from the walls' reflections.
  {
    name: 'plain textured sphere, env=none (no background)',
    kind: 'textured',
    settings: view('table', { env: 'none' }),
    quality: q,
    measuresError: false,
  },
  THREE_IRIDESCENCE_ROW,
  FOURIER_ROW,
  fourier(2, ' (three.js/glTF keep m ≤ 2)'),
  fourier(3, ' (Blender Cycles keeps m ≤ 3)'),
  { ...exact(45), smoke: false },
  EXACT_ROW,
  table({ fill: 'binned', thickEndCellNm: 0 }, ' (before: the previous default)'),
  DEFAULT_TABLE_ROW,
  // A film on a metal (docs/physics.md#absorbing-media-on-the-gpu), the default table's frame cost
  // next to the constant film's above: the table is filled from the dispersive bins (Fresnel per row
  // and bin) and its inside half left black (opaque inside); a frame is the same lookup. No error
  // columns: the grids are the soap film's.
  sceneStep(
    'default table, nFilm=TiO2 on nInside=Ti (a film on a metal: dispersive bins, opaque inside)',
    { nFilm: 'TiO2', nInside: 'Ti' },
    true,
  ),
  table({ thickEndCellNm: 0 }),
  table({ width: 1024, rows: 64 }),
  table({ cosPower: 1.5 }),
  table({ width: 512, rows: 64 }),
  table({}, ' (default layout)', 'half'),
  sceneStep('default table, uniform field (swirl off)', { field: 'uniform' }),
  sceneStep('default table, drainage field (swirl off)', { field: 'drainage' }),
  // The flowing film simulated on the GPU each frame, at each fixed grid, in real time.
  ...FLOW_ROW_GRIDS.map((n) => ({ ...flowRow(n), ...(n === Math.max(...FLOW_ROW_GRIDS) && { smoke: false as const }) })),
  sceneStep('default table, front wall only', { sides: 'front' }),
  // What the environment costs: none reflects the light's white and draws no background; the
  // default sky; each HDR map (three lookups a fragment, AgX). A coloured one is reflected through the
  // film's environment matrix.
  {
    ...sceneStep("default table, walls reflecting the light's white, sky behind (before: no environment reflections)", {}),
    earlierModel: 'whiteWalls',
  },
  // The film's environment matrix against the film's XYZ times the sky's RGB (one table plane, one lookup a wall), frames taking turns.
  {
    ...sceneStep("default table, the sky through the film's environment matrix (three table planes, three lookups a wall)", {}),
    takesTurnsWith: 'rgbProduct',
  },
  sceneStep('default table, env=none (no environment to reflect or show)', { env: 'none' }),
  // A uniform white room: the walls show env=none's film colours, through M (three table planes, three lookups a wall), and a background.
  sceneStep('default table, env=color:1,1,1 (a white room: the film as env=none, through its environment matrix)', {
    env: { color: [1, 1, 1] },
  }),
  ...HDR_ENVIRONMENTS.map((env) => sceneStep(`default table, env=${env} (HDR map reflected on both walls, AgX)`, { env })),
  // A dispersive film (water at 20 °C) in each mode, against the same modes' rows with n 1.33 above.
  { ...table({}, ', nFilm=water (150 bins, Fresnel per row and bin)'), settings: view('table', { nFilm: 'water' }) },
  {
    ...fourier(q.airySeriesMaxOrders, ", nFilm=water (the shader's fallback: 150 dispersive bins per fragment; the app draws the table)"),
    settings: view('fourier', { nFilm: 'water' }),
    smoke: false,
  },
  { ...exact(90), name: 'exact, nFilm=water (150 bins, Fresnel per bin)', settings: view('exact', { nFilm: 'water' }), smoke: false },
  // Stacks of films (docs/gpu.md#stacks-of-films) against the default table and exact rows above: the
  // table filled by the recursion per bin (a stack of fixed layers is the same at every thickness:
  // two columns), a frame the same lookup; `exact` runs the recursion per fragment. No error
  // columns: the grids are the soap film's (tests/e2e/stackParity.spec.ts holds the stacks').
  sceneStep('default table, 16-layer stack of fixed layers (Bragg mirror (2.35:56.6/1.46:91.1)*8 on 1.52)', BRAGG_16, true),
  sceneStep('default table, 16-layer stack following the field ((1.68:d/1.43:30)*8 on 1.53)', NACRE_16, true),
  {
    name: 'exact, 16-layer stack (Bragg mirror, 150 bins, the recursion per bin)',
    kind: 'bubble',
    settings: view('exact', BRAGG_16),
    quality: q,
    measuresError: false,
    smoke: false,
  },
];

/** The flowing film's simulation speed, on the GPU and in the float64 twin (flowSpeed.ts): with every row, or when this name is picked. */
export const FLOW_SPEED_ROW = 'flow simulation: steps per second on the GPU and of the float64 twin, draws per step';

/** The spectral material's figures (the example page, the app bundle): they run with every row, or when this name is picked. */
export const MATERIALS_ROW = 'materials page: spectral film against three.js iridescence';

/** The WebGPU entry's figures on three.js's WebGPURenderer, both backends (nodeFigures.ts): they run with every row, or when this name is picked. */
export const NODE_ROW = "WebGPURenderer: three.js's node iridescence and the WebGPU entry, on its WebGL2 and WebGPU backends";

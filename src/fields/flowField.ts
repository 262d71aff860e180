import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { cubeFaceColumns } from '../physics/filmDynamics/cubeSphereFaces.ts';
import { cubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo, padField, paddedSampler } from '../physics/filmDynamics/cubeSphereSampler.ts';
import { flowNumbers } from '../physics/filmDynamics/flowNumbers.ts';
import { FLOW_PARAMETERS, type FlowParameterKey, type FlowParameters } from '../physics/filmDynamics/flowParameters.ts';
import { initialFilm } from '../physics/filmDynamics/initialFilm.ts';
import { type NumberSetting, type TimelessInput, type Vec3, flagSetting, numberSetting, thicknessField } from './thicknessField.ts';

/** The flow's mean thickness: the view's, at least the model's lowest (its numbers divide by η0). */
const THICKNESS_MIN_NM = FLOW_PARAMETERS.find((r) => r.key === 'thicknessNm')!.domain.min;
/**
 * The film table covers this many times the thickest the film is at its start or at rest (the
 * settled profile's bottom): room for the transients between; thicker film is drawn at the table's end.
 */
const TABLE_MARGIN = 1.5;

/** Settings of the flowing film's own whose values are flow parameters: each one's URL name and slider step, its domain, default and whether it is whole its FLOW_PARAMETERS row's. */
function flowParameterSettings<K extends FlowParameterKey>(given: Record<K, readonly [url: string, step: number]>) {
  const setting = ([key, [url, step]]: [string, readonly [string, number]]) => {
    const r = FLOW_PARAMETERS.find((row) => row.key === key)!;
    return [key, numberSetting(url, r.domain, r.defaultValue, r.integer ? 'integer' : step, 'flow')];
  };
  return Object.fromEntries(Object.entries<readonly [string, number]>(given).map(setting)) as Record<K, NumberSetting<'flow'>>;
}

/**
 * The flowing film's own settings, in the panel's flow folder. `simSpeed` and `gridN` are what a
 * view draws when the page leaves them to it (a frozen view; the page's own rows,
 * src/settings/viewParameters.ts, take `auto`); `renew`: a new bubble after a burst (the GPU's own,
 * src/gpuFilmDynamics/renewFilm.ts).
 */
const FLOW_SETTINGS = {
  ...flowParameterSettings({
    radiusMm: ['radius', 1],
    surfactantMolM2: ['surfactant', 1e-9],
    evaporationNmS: ['evaporation', 1],
    windMps: ['wind', 0.01],
    windTurnDegS: ['windTurn', 1],
    seed: ['seed', 1],
    simSpeed: ['simSpeed', 0.01],
    gridN: ['grid', 1],
  }),
  renew: flagSetting('renew', true, 'flow'),
};

/** The flow parameters the settings give: every row of FLOW_PARAMETERS is a settings field of the same name. */
export function flowParametersOf(s: TimelessInput<typeof FLOW_SETTINGS>): FlowParameters {
  const given: Partial<Record<FlowParameterKey, number>> = s;
  const values = Object.fromEntries(FLOW_PARAMETERS.map((r) => [r.key, given[r.key] ?? r.defaultValue]));
  return { ...(values as FlowParameters), thicknessNm: Math.max(THICKNESS_MIN_NM, s.thicknessNm) };
}

/** The simulation's direction (z up, docs/flow.md#the-grid) of a point of the view (y up): a quarter turn about x. */
export const flowDirection = ([x, y, z]: Vec3): Vec3 => [x, -z, y];

/** The film's start (η per cell, padded for sampling) for the last grid and seed asked for. */
let start: { key: string; padded: Float64Array } | null = null;
function startFilm(gridN: number, seed: number) {
  const key = `${gridN} ${seed}`;
  if (start?.key !== key) {
    const grid = cubeSphereGrid(gridN);
    start = { key, padded: padField(cubeSphereHalo(grid), initialFilm(grid, seed).eta, 1) };
  }
  return start;
}

/**
 * The coarse grid the film's start is sampled on where the grid it is simulated on is not needed:
 * to size the table (which then need not change with the grid), and to show a film in the frame
 * before its simulation is made (src/gpuFilmDynamics/flowFieldState.ts). Its bumps are smooth over several
 * cells of it, and it is cheap to make.
 */
export const COARSE_START_GRID_N = 16;
/** The film's start on COARSE_START_GRID_N, and its thickest (in η0), for the last seed asked for. */
let coarseStart: { seed: number; film: ReturnType<typeof initialFilm>; maxEta: number } | null = null;
function coarseStartOf(seed: number) {
  if (coarseStart?.seed !== seed) {
    const film = initialFilm(cubeSphereGrid(COARSE_START_GRID_N), seed);
    coarseStart = { seed, film, maxEta: Math.max(...film.eta) };
  }
  return coarseStart;
}
/** The film's start (initialFilm) on COARSE_START_GRID_N: made once per seed for the table's range and the frame before the simulation. */
export const coarseStartFilm = (seed: number): ReturnType<typeof initialFilm> => coarseStartOf(seed).film;

/**
 * The thickest the film is at its start or settled (h̄ · 2a/(1 − e^(−2a)) at the bottom of the
 * resting profile h̄ (a/sinh a) e^(−a cos θ), a = g/M: docs/flow.md#the-stationary-film), times
 * TABLE_MARGIN, within the film stack's domain.
 */
function flowMaxNm(p: FlowParameters): number {
  const numbers = flowNumbers(p);
  const a = numbers.gravity / numbers.marangoni;
  const settledBottom = (2 * a) / -Math.expm1(-2 * a);
  const factor = Math.max(settledBottom, coarseStartOf(p.seed).maxEta);
  return Math.min(FILM_STACK_DOMAIN.thicknessNm.max, Math.max(1, TABLE_MARGIN * factor * p.thicknessNm));
}

/**
 * The flowing soap film (shaders/fields/flowField.glsl): the full thickness h̄·η sampled from the
 * simulation of src/physics/filmDynamics/, run on the GPU by src/gpuFilmDynamics/ (the view's FieldState), bilinear
 * within a cube face and seamless across them. Its TypeScript twin is the film at its start.
 */
export const flowField = thicknessField({
  glsl: 'flowField.glsl',
  settings: FLOW_SETTINGS,
  // Its film is simulated to the time timeSeconds × simSpeed (src/gpuFilmDynamics/flowFieldState.ts).
  reads: ['thicknessNm', 'timeSeconds'],
  uniforms: () => ({
    uThicknessNm: { value: 500 },
    uFlowMaxThicknessNm: { value: 1 },
    uFlowFilm: { value: null },
    uFlowGridN: { value: 1 },
    uCubeFaces: { value: Float32Array.from(cubeFaceColumns()) },
  }),
  derive: flowParametersOf,
  update: (u, _, drawn) => {
    u.uThicknessNm!.value = drawn.derived.thicknessNm;
    u.uFlowMaxThicknessNm!.value = drawn.maxThicknessNm;
  },
  thicknessAt: (p, s) => {
    const parameters = flowParametersOf(s);
    const { gridN, seed, thicknessNm } = parameters;
    const out = new Float64Array(1);
    paddedSampler(cubeSphereHalo(cubeSphereGrid(gridN)), 1)(startFilm(gridN, seed).padded, ...flowDirection(p), out);
    return Math.min(flowMaxNm(parameters), Math.max(0, thicknessNm * out[0]!));
  },
  maxThicknessNm: (_, parameters) => flowMaxNm(parameters),
  animates: true,
  evolves: true,
});

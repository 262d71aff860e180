import { ShaderMaterial } from 'three';
import { LOG_MEAN_SERIES_BELOW } from '../physics/filmDynamics/logarithmicMean.ts';
import { FULLSCREEN_VERTEX } from '../gpu/fullscreenPass.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { flowLayoutDefines } from './flowLayouts.ts';
import { flowTexelDefines } from './flowTexels.ts';
import type { FlowUniformSet, FlowUniformSets } from './flowUniforms.ts';

/** The angular width of a blow's patch of air (radians): about a sixth of the bubble across. */
export const BLOW_WIDTH_RAD = 0.3;

/** The grid passes' sets: the atlas, the mesh and the film a step reads. */
const GRID = ['flowAtlas.glsl', 'cubeSphereGrid.glsl', 'filmStep_pars.glsl'] as const;
/** …and the faces, for the passes that sample a padded field at a direction. */
const SAMPLING_GRID = [...GRID, 'cubeSphereFaces.glsl'] as const;

/**
 * The uniform sets of each pass's file (flowUniforms.ts): its own and those of the files it
 * includes, as three's shaders merge a UniformsLib entry for each `_pars` chunk they include.
 */
const FILE_SETS = {
  'reconstructCellVelocity.glsl': GRID,
  'padField_pars.glsl': ['flowAtlas.glsl', 'cubeSphereFaces.glsl', 'padField_pars.glsl'],
  'predictEdgeVelocity.glsl': [...SAMPLING_GRID, 'predictEdgeVelocity.glsl'],
  'solveSurfactant.glsl': [...GRID, 'solveSurfactant.glsl'],
  'transportFilm.glsl': [...GRID, 'transportFilm.glsl'],
  'filmSimulation.glsl': ['flowAtlas.glsl', 'filmStep_pars.glsl', 'filmSimulation.glsl'],
  'ruptureFilm.glsl': [...SAMPLING_GRID, 'renewFilm.glsl', 'ruptureFilm.glsl'],
  'renewFilm.glsl': ['renewFilm.glsl'],
} as const satisfies Record<string, readonly FlowUniformSet[]>;

/**
 * Each pass: the GLSL file of the twin's module it mirrors and the call that computes a texel. The
 * halo pass's function takes its textures as arguments, which its `_pars` file declares.
 */
export const PASSES = {
  reconstruct: ['reconstructCellVelocity.glsl', 'tfcReconstructCellVelocity()'],
  pad: ['padField_pars.glsl', 'tfcPadField(uHaloTaps, uField)'],
  predict: ['predictEdgeVelocity.glsl', 'tfcPredictEdgeVelocity()'],
  weights: ['solveSurfactant.glsl', 'tfcSurfactantWeights()'],
  system: ['solveSurfactant.glsl', 'tfcSurfactantSystem()'],
  sweep: ['solveSurfactant.glsl', 'tfcChebyshevSweep()'],
  correct: ['solveSurfactant.glsl', 'tfcCorrectEdgeVelocity()'],
  limiter: ['transportFilm.glsl', 'tfcTransportLimiter()'],
  flux: ['transportFilm.glsl', 'tfcTransportFlux()'],
  update: ['transportFilm.glsl', 'tfcTransportUpdate()'],
  start: ['filmSimulation.glsl', 'tfcStartFilm()'],
  evaporate: ['filmSimulation.glsl', 'tfcEvaporate()'],
  rupture: ['ruptureFilm.glsl', 'tfcRuptureFilm()'],
  ruptureRows: ['ruptureFilm.glsl', 'tfcRuptureRows()'],
  openHoles: ['ruptureFilm.glsl', 'tfcOpenHoles()'],
  growRims: ['ruptureFilm.glsl', 'tfcGrowRims()'],
  emptyHoles: ['ruptureFilm.glsl', 'tfcEmptyHoles()'],
  burstSteps: ['renewFilm.glsl', 'tfcBurstSteps()'],
} as const satisfies Record<string, readonly [keyof typeof FILE_SETS, string]>;
export type PassName = keyof typeof PASSES;

/** The defines of every pass: the flow's layouts and texel records (flowLayouts.ts, flowTexels.ts) and the twin's constants the GLSL reads. */
export const flowPassDefines = (): Record<string, number> => ({
  ...flowLayoutDefines(),
  ...flowTexelDefines(),
  TFC_LOG_MEAN_SERIES_BELOW: LOG_MEAN_SERIES_BELOW,
  TFC_BLOW_WIDTH_RAD: BLOW_WIDTH_RAD,
});

/**
 * A material per pass: its file's GLSL with a main writing the call's texel, and the uniforms of its
 * file's sets, each uniform's object shared with every other pass that reads it.
 */
export function passMaterials(sets: FlowUniformSets): Record<PassName, ShaderMaterial> {
  const defines = flowPassDefines();
  const material = ([file, texel]: (typeof PASSES)[PassName]) =>
    new ShaderMaterial({
      defines,
      uniforms: Object.fromEntries(FILE_SETS[file].flatMap((set) => Object.entries(sets[set]))),
      vertexShader: FULLSCREEN_VERTEX,
      fragmentShader: `${shaderSource(file)}\nvoid main() { gl_FragColor = ${texel}; }\n`,
    });
  return Object.fromEntries(Object.entries(PASSES).map(([name, pass]) => [name, material(pass)])) as Record<PassName, ShaderMaterial>;
}

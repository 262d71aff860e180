import type { IUniform, Texture } from 'three';
import { cubeFaceColumns } from '../physics/filmDynamics/cubeSphereFaces.ts';
import type { CubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import { PURE_SURFACE_TENSION_N_M, VELOCITY_SCALE_M_S } from '../physics/filmDynamics/flowConstants.ts';
import { type FlowNumbers, taylorCulickSpeedMps } from '../physics/filmDynamics/flowNumbers.ts';
import type { FlowParameters } from '../physics/filmDynamics/flowParameters.ts';
import { rimLeadRad, rimThicknessFloorNm } from '../physics/filmDynamics/ruptureFilm.ts';
import { surfaceWind } from '../physics/filmDynamics/windDirection.ts';
import type { FlowGridTextures } from './flowGridTextures.ts';
import { SWEEP_GUESS, SWEEP_PREVIOUS_GUESS } from './flowTexels.ts';

/** What the uniforms' values are made of: the simulation's parameters, numbers, grid, step and grid textures. */
export interface FlowUniformInputs {
  readonly parameters: FlowParameters;
  readonly numbers: FlowNumbers;
  readonly grid: CubeSphereGrid;
  /** The fixed step Δt, in R/U. */
  readonly dt: number;
  /** The transport's sub-steps per step (transportSubsteps). */
  readonly transportSubsteps: number;
  /** The burst's count of steps at which the film renews (renewFilm.ts), 0 for never. */
  readonly renewSteps: number;
  readonly textures: FlowGridTextures;
}

const value = (v: unknown): IUniform => ({ value: v });
/** A texture a pass reads, pointed at its target before the draw. */
const input = (): IUniform<Texture | null> => ({ value: null });

/** rimSpeedFactor·√(2γ_a/(ρh̄)) in U: the rim's speed in film of η = 1 and Γ = 0 (ruptureFilm.glsl). */
const rimSpeed = (p: FlowParameters, n: FlowNumbers): number =>
  (p.rimSpeedFactor * taylorCulickSpeedMps(PURE_SURFACE_TENSION_N_M, 2 * n.halfThicknessM)) / VELOCITY_SCALE_M_S;

/**
 * The uniform sets of the flow's passes, each under the file of shaders/gpuFilmDynamics/ that declares it and
 * made by its one factory: a pass's material holds the sets of the files its shader is made of
 * (flowPasses.ts), and tests/unit/gpuFilmDynamics/flowUniforms.test.ts holds both to what the GLSL declares.
 */
export const FLOW_UNIFORM_SETS = {
  'flowAtlas.glsl': ({ grid }: FlowUniformInputs) => ({ uFlowGridN: value(grid.n) }),
  'cubeSphereFaces.glsl': () => ({ uCubeFaces: value(Float32Array.from(cubeFaceColumns())) }),
  'cubeSphereGrid.glsl': ({ textures: t }: FlowUniformInputs) => ({
    uCellGeometry: value(t.uCellGeometry),
    uCellEdges: value(t.uCellEdges),
    uCellNeighbors: value(t.uCellNeighbors),
    uEdgeCells: value(t.uEdgeCells),
    uEdgeNormal: value(t.uEdgeNormal),
    uEdgeMid: value(t.uEdgeMid),
  }),
  'padField_pars.glsl': ({ textures }: FlowUniformInputs) => ({ uHaloTaps: value(textures.uHaloTaps), uField: input() }),
  'filmStep_pars.glsl': ({ dt }: FlowUniformInputs) => ({ uFilm: input(), uEdgeVelocity: input(), uDt: value(dt) }),
  'filmSimulation.glsl': ({ numbers, dt }: FlowUniformInputs) => ({ uEvaporationLoss: value(numbers.evaporation * dt) }),
  'predictEdgeVelocity.glsl': ({ numbers }: FlowUniformInputs) => ({
    uCellVelocity: input(),
    uPaddedCellVelocity: input(),
    uAirFriction: value(numbers.airFriction),
    uGravity: value(numbers.gravity),
    uMarangoni: value(numbers.marangoni),
    // The wind at the film's start, along +x; a turning wind's is set before each step (gpuFilmSimulation.ts).
    uSurfaceWind: value(surfaceWind(numbers, 0)),
    uBlowCenter: value([0, 0, 1]),
    uBlowVelocity: value([0, 0, 0]),
  }),
  'solveSurfactant.glsl': () => ({
    uPrediction: input(),
    uSurfactantWeights: input(),
    uSurfactantRhs: input(),
    uGuess: input(),
    uGuessChannel: value(SWEEP_GUESS),
    uPreviousGuessChannel: value(SWEEP_PREVIOUS_GUESS),
    uChebyshevMomentum: value(0),
    uChebyshevStep: value(1),
    uSolvedGamma: input(),
  }),
  'transportFilm.glsl': ({ dt, transportSubsteps }: FlowUniformInputs) => ({
    uTransportDt: value(dt / transportSubsteps),
    uLimiter: input(),
    uFlux: input(),
  }),
  'renewFilm.glsl': ({ renewSteps }: FlowUniformInputs) => ({ uBurst: input(), uRenewSteps: value(renewSteps), uHoles: input() }),
  'ruptureFilm.glsl': ({ parameters, numbers, grid }: FlowUniformInputs) => ({
    uRuptureEta: value(numbers.ruptureEta),
    uRuptureGamma: value(numbers.ruptureGamma),
    uRuptureRows: input(),
    // No puncture until one is asked for (FlowStep.puncture).
    uPuncture: value([0, 0, 1]),
    uPunctured: value(0),
    uPaddedFilm: input(),
    uRimSpeed: value(rimSpeed(parameters, numbers)),
    uRimEtaFloor: value(rimThicknessFloorNm(parameters) / parameters.thicknessNm),
    uRimLead: value(rimLeadRad(grid.n)),
    uStartFilm: input(),
  }),
} as const;

export type FlowUniformSet = keyof typeof FLOW_UNIFORM_SETS;
type KeysOfEach<T> = T extends unknown ? keyof T : never;
/** Every uniform of the flow's passes by name. */
export type FlowUniformName = KeysOfEach<ReturnType<(typeof FLOW_UNIFORM_SETS)[FlowUniformSet]>>;
export type FlowUniformSets = Record<FlowUniformSet, Readonly<Partial<Record<FlowUniformName, IUniform>>>>;

/** Every set, made once: the passes share each uniform's object, so a value set once reaches each pass that reads it. */
export const flowUniformSets = (inputs: FlowUniformInputs): FlowUniformSets =>
  Object.fromEntries(Object.entries(FLOW_UNIFORM_SETS).map(([file, make]) => [file, make(inputs)])) as FlowUniformSets;

/** The uniforms of all sets by name. */
export const allFlowUniforms = (sets: FlowUniformSets): Record<FlowUniformName, IUniform> =>
  Object.fromEntries(Object.values(sets).flatMap((set) => Object.entries(set))) as Record<FlowUniformName, IUniform>;

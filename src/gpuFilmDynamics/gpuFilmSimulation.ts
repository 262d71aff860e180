import type { DataTexture, Texture, WebGLRenderTarget, WebGLRenderer } from 'three';
import { type CubeSphereGrid, cubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo } from '../physics/filmDynamics/cubeSphereSampler.ts';
import { VELOCITY_SCALE_M_S } from '../physics/filmDynamics/flowConstants.ts';
import { type FlowNumbers, flowNumbers } from '../physics/filmDynamics/flowNumbers.ts';
import { type FlowParameters, validateFlowParameters } from '../physics/filmDynamics/flowParameters.ts';
import { initialFilm } from '../physics/filmDynamics/initialFilm.ts';
import { checkPunctureDirection } from '../physics/filmDynamics/filmSimulation.ts';
import type { ChebyshevSchedule } from '../physics/filmDynamics/chebyshevSchedule.ts';
import { surfactantSolveSchedule } from '../physics/filmDynamics/solveSurfactant.ts';
import { type TimeStepRule, timeStep, transportSubsteps } from '../physics/filmDynamics/timeStep.ts';
import { surfaceWind, windAngleRad } from '../physics/filmDynamics/windDirection.ts';
import { floatTexture } from '../gpu/floatRow.ts';
import { cellTexelIndex, faceAtlasSize } from './flowAtlas.ts';
import { type FlowGridTextures, flowGridTextures } from './flowGridTextures.ts';
import { FlowStep } from './flowStep.ts';
import { paddedStartTexture, startFilmRecords } from './paddedStart.ts';
import { FLOW_FILM } from './flowTexels.ts';
import { flowUniformSets } from './flowUniforms.ts';
import { renewSteps } from './renewFilm.ts';

/**
 * The targets that hold the film's state, for reading it back, each texel a record of
 * flowTexels.ts: the film (FLOW_FILM) per cell of the cell atlas, and padded, u·n per edge of the
 * edge atlas (EDGE_VELOCITY), and the hole table (flowLayouts.ts).
 */
export interface FilmStateTargets {
  readonly film: WebGLRenderTarget;
  /** The padded film as `paddedFilm` last made it. */
  readonly paddedFilm: WebGLRenderTarget;
  readonly edgeVelocity: WebGLRenderTarget;
  readonly holes: WebGLRenderTarget;
}

/**
 * The flowing film of src/physics/filmDynamics/ on the GPU, pass for pass (docs/flow.md#the-gpu-port): the
 * same grid, parameters, start and fixed step Δt, each of the twin's passes one fragment-shader
 * draw into RGBA float render targets of the renderer it is given (FlowStep, in the cell, padded
 * and edge atlases of flowAtlas.ts). `step` runs whole steps; `paddedFilm` is the film to sample.
 * With `renew` a new bubble follows a burst (renewFilm.ts); the twin has no such option. `puncture`
 * bursts it where it is tapped.
 */
export class GpuFilmSimulation {
  readonly parameters: FlowParameters;
  readonly numbers: FlowNumbers;
  readonly grid: CubeSphereGrid;
  /** The fixed step in R/U, and in seconds. */
  readonly dt: number;
  readonly stepSeconds: number;
  /** The surfactant solve's Chebyshev iterations, the twin's for the same parameters and Δt. */
  readonly solveSchedule: ChebyshevSchedule;
  /** The transport's sub-steps per step, the twin's. */
  readonly transportSubsteps: number;
  /** Steps taken since the start. */
  steps = 0;
  private textures: FlowGridTextures;
  /** The film at its start (startFilmRecords, float64 from initialFilm rounded once); its padded film made on the CPU (startPaddedFilm). */
  private start: DataTexture;
  private startPadded: DataTexture | null = null;
  private readonly passes: FlowStep;
  /** Whether the film target holds the start (false until the first draw after creation, reset or a lost context). */
  private started = false;
  /** The steps the padded film was made for. */
  private paddedAt = -1;

  /**
   * A film at its start, every parameter checked first (validateFlowParameters); Δt sized by the
   * twin's rule `timeStep` (the flow's unless given, as createFilmSimulation's).
   */
  constructor(
    renderer: WebGLRenderer,
    given: Partial<Record<string, unknown>> = {},
    options: { readonly renew?: boolean; readonly timeStep?: TimeStepRule } = {},
  ) {
    this.parameters = validateFlowParameters(given);
    this.numbers = flowNumbers(this.parameters);
    this.grid = cubeSphereGrid(this.parameters.gridN);
    this.dt = (options.timeStep ?? timeStep)(this.grid, this.numbers);
    this.solveSchedule = surfactantSolveSchedule(this.grid, this.numbers, this.dt);
    this.transportSubsteps = transportSubsteps(this.grid, this.numbers, this.dt);
    this.stepSeconds = this.dt * this.numbers.timeScaleS;
    this.textures = flowGridTextures(this.grid, cubeSphereHalo(this.grid));
    this.start = this.startTexture();
    const sets = flowUniformSets({
      parameters: this.parameters,
      numbers: this.numbers,
      grid: this.grid,
      dt: this.dt,
      transportSubsteps: this.transportSubsteps,
      renewSteps: renewSteps(options.renew ?? false, this.stepSeconds),
      textures: this.textures,
    });
    this.passes = new FlowStep(renderer, sets, this.grid.n, this.solveSchedule, this.transportSubsteps);
  }

  private startTexture(): DataTexture {
    const film = startFilmRecords(this.grid, initialFilm(this.grid, this.parameters.seed));
    const texel = FLOW_FILM.floats;
    const size = faceAtlasSize(this.grid.n);
    const data = new Float32Array(texel * size.width * size.height);
    for (let c = 0; c < this.grid.cellCount; c++)
      data.set(film.subarray(texel * c, texel * c + texel), texel * cellTexelIndex(this.grid.n, c));
    return floatTexture(data, size.width, size.height);
  }

  /**
   * The padded film at its start, made on the CPU (paddedStartTexture), to draw before any of the
   * simulation's programs is compiled. Made on first use, and let go once the simulation pads its
   * own film.
   */
  get startPaddedFilm(): Texture {
    this.startPadded ??= paddedStartTexture(this.grid, initialFilm(this.grid, this.parameters.seed));
    return this.startPadded;
  }

  /** Back to the start (drawn with the next step or padded film). */
  reset(): void {
    this.started = false;
    this.steps = 0;
    this.paddedAt = -1;
  }

  /**
   * Air blown at a direction (unit, the simulation's frame) with a velocity in m/s (its part
   * tangent there counts) for the steps that follow, until `blow` is called again; a zero
   * velocity is still air (the twin's air).
   */
  blow(center: readonly [number, number, number], velocityMps: readonly [number, number, number]): void {
    const along = velocityMps[0] * center[0] + velocityMps[1] * center[1] + velocityMps[2] * center[2];
    this.passes.set('uBlowCenter', [...center]);
    this.passes.set(
      'uBlowVelocity',
      velocityMps.map((v, k) => (v - along * center[k]!) / VELOCITY_SCALE_M_S),
    );
  }

  /** Runs `count` whole steps Δt, each in the wind's direction at its start (the twin's). */
  step(count = 1): void {
    if (count <= 0) return;
    const turns = this.parameters.windTurnDegS !== 0;
    this.passes.withTargets(() => {
      this.ensureStarted();
      for (let k = 0; k < count; k++) {
        if (turns) this.passes.set('uSurfaceWind', surfaceWind(this.numbers, windAngleRad(this.parameters, this.steps * this.stepSeconds)));
        this.passes.step(this.numbers.evaporation > 0);
        this.steps++;
      }
    });
  }

  /**
   * Bursts the bubble where it is tapped: pricks the film at the direction (x, y, z) from the
   * bubble's centre, in the simulation's frame (z up; a view's y-up point p is (p.x, −p.z, p.y)),
   * of any length but 0. A hole opens there, if one of the MAX_HOLES slots is free, and from the
   * next step its rim runs outward at the Taylor–Culick speed until the film is gone (or, with
   * `renew`, a new bubble follows). Its reference is the twin's punctureFilm, which
   * tests/e2e/flowBurst.spec.ts compares it with. A direction that is not three finite numbers, or
   * is 0, throws a ParameterError naming `puncture` (checkPunctureDirection).
   */
  puncture(x: number, y: number, z: number): void {
    checkPunctureDirection(x, y, z);
    this.passes.withTargets(() => {
      this.ensureStarted();
      this.passes.puncture(x, y, z);
    });
  }

  /** The padded film (a FLOW_FILM record per padded texel), its ghosts filled, at the steps taken: what tfcSamplePadded reads. */
  get paddedFilm(): Texture {
    const t = this.passes.targets;
    if (this.paddedAt !== this.steps || !this.started) {
      this.passes.withTargets(() => {
        this.ensureStarted();
        this.passes.pad(t.film.read, t.paddedFilm);
      });
      this.paddedAt = this.steps;
      // The start padded on the CPU is drawn no more.
      this.startPadded?.dispose();
      this.startPadded = null;
    }
    return t.paddedFilm.texture;
  }

  /** The targets that hold the film at the steps taken (the start drawn first if it is not yet). */
  get stateTargets(): FilmStateTargets {
    this.passes.withTargets(() => this.ensureStarted());
    const t = this.passes.targets;
    return {
      film: t.film.read,
      paddedFilm: t.paddedFilm,
      edgeVelocity: t.edgeVelocity,
      holes: t.holes.read,
    };
  }

  private ensureStarted(): void {
    if (this.started) return;
    this.passes.start(this.start);
    this.started = true;
  }

  /**
   * New GPU objects after a lost context, the film back at its start. The lost context's targets
   * and textures are let go, not disposed: three would delete objects of the lost context in the new
   * one (a WebGL warning). The programs are three's to make anew.
   */
  invalidate(): void {
    this.textures = flowGridTextures(this.grid, cubeSphereHalo(this.grid));
    this.start = this.startTexture();
    this.startPadded = null;
    for (const [name, texture] of Object.entries(this.textures)) this.passes.set(name as keyof FlowGridTextures, texture);
    this.passes.invalidate();
    this.reset();
  }

  dispose(): void {
    this.passes.dispose();
    for (const texture of [this.start, this.startPadded, ...Object.values(this.textures)]) texture?.dispose();
  }
}

import type { DataTexture, WebGLRenderer } from 'three';
import { COARSE_START_GRID_N, coarseStartFilm, flowDirection } from '../fields/flowField.ts';
import type { FieldSettings } from '../fields/fields.ts';
import type { FieldState, FieldUniforms, SimulationGrid, Vec3 } from '../fields/thicknessField.ts';
import { cubeSphereGrid } from '../physics/filmDynamics/cubeSphereGrid.ts';
import { FLOW_PARAMETERS, type FlowParameters } from '../physics/filmDynamics/flowParameters.ts';
import { GpuFilmSimulation } from './gpuFilmSimulation.ts';
import { paddedStartTexture } from './paddedStart.ts';

/** Film seconds a blow lasts (a drag blows anew with each move). */
const BLOW_FILM_SECONDS = 0.05;
/** Still air. */
const CALM: Vec3 = [0, 0, 0];

/** Where `finish` reads its texel (the film's targets are RGBA float). */
const TEXEL = new Float32Array(4);

/** What a simulation is made of: the flow's parameters and whether a new bubble follows a burst. */
interface FilmMade {
  readonly parameters: FlowParameters;
  readonly renew: boolean;
}
const sameFilm = (a: FilmMade | null, b: FilmMade): boolean =>
  a !== null && a.renew === b.renew && FLOW_PARAMETERS.every((r) => a.parameters[r.key] === b.parameters[r.key]);

/** A relative slack so that k·Δt film seconds take k steps despite rounding (the twin's advanceFilm's). */
const STEP_SLACK = 1e-9;

/**
 * The flow field's film (src/fields/flowField.ts) as the view keeps it: a GpuFilmSimulation of the
 * flow's parameters as the frame derives them (the field's `derive`, flowParametersOf), given to
 * each advance, advanced in whole fixed steps to the film time timeSeconds × simSpeed, so
 * the same settings give the same film on every load whatever the display rate; made anew from its
 * start when a parameter changes or the time goes back. With the settings' `renew` a new bubble
 * follows a burst (src/gpuFilmDynamics/renewFilm.ts). An animating frame shows a new film at its start on the
 * coarse grid (COARSE_START_GRID_N, cheap to make) and makes its simulation in the next frame, so
 * the first frame of a page costs little more than the bubble's own.
 */
export class FlowFieldState implements FieldState<FlowParameters> {
  private simulation: GpuFilmSimulation | null = null;
  /** What the film shown is made of (null: none). */
  private film: FilmMade | null = null;
  /** The start on the coarse grid, shown in the frame before a simulation is made. */
  private preview: DataTexture | null = null;
  /** The time shown, in the settings' seconds. */
  timeSeconds = 0;
  /** The blow the next steps take (the simulation's frame) and the film seconds it has left. */
  private blowing: { readonly center: Vec3; readonly velocity: Vec3; seconds: number } | null = null;

  constructor(private readonly renderer: WebGLRenderer) {}

  /** The grid of the simulation the film lives in, made once per simulation (FieldState.grid). */
  private simulationGrid: { readonly sim: GpuFilmSimulation; readonly grid: SimulationGrid } | null = null;

  get grid(): SimulationGrid | null {
    const sim = this.simulation;
    if (sim && this.simulationGrid?.sim !== sim) this.simulationGrid = { sim, grid: { gridN: sim.grid.n, stepSeconds: sim.stepSeconds } };
    return sim && this.simulationGrid!.grid;
  }

  get steps(): number {
    return this.simulation?.steps ?? 0;
  }

  finish(): void {
    if (this.simulation) this.renderer.readRenderTargetPixels(this.simulation.stateTargets.film, 0, 0, 1, 1, TEXEL);
  }

  advance(u: FieldUniforms, s: FieldSettings, parameters: FlowParameters, maxSteps: number): boolean {
    const film: FilmMade = { parameters, renew: s.renew };
    const changed = !sameFilm(this.film, film);
    const shownFirst = Number.isFinite(maxSteps);
    if (changed && shownFirst) {
      // A new film in an animating frame: its start on the coarse grid now, its simulation in the next frame.
      this.simulation?.dispose();
      this.simulation = null;
      this.film = film;
      this.preview?.dispose();
      this.preview = paddedStartTexture(cubeSphereGrid(COARSE_START_GRID_N), coarseStartFilm(parameters.seed));
      u.uFlowFilm!.value = this.preview;
      u.uFlowGridN!.value = COARSE_START_GRID_N;
      this.timeSeconds = 0;
      return false;
    }
    const made = !this.simulation || changed;
    if (made) this.make(film);
    const sim = this.simulation!;
    const wanted = Math.floor(((s.timeSeconds * parameters.simSpeed) / sim.stepSeconds) * (1 + STEP_SLACK));
    if (wanted < sim.steps) {
      // The film starts again: a blow still under way was on the film given up, not on its start.
      sim.reset();
      this.blowing = null;
    }
    // An animating frame that made the simulation shows its start; its steps, compiling its programs,
    // begin in the frame after. A frame that must show the time steps at once.
    const ready = !(made && shownFirst);
    const count = ready ? Math.min(wanted - sim.steps, maxSteps) : 0;
    this.step(sim, count);
    // In the frame that made it, the film's start as made on the CPU.
    u.uFlowFilm!.value = ready ? sim.paddedFilm : sim.startPaddedFilm;
    u.uFlowGridN!.value = sim.grid.n;
    const reached = sim.steps === wanted;
    // Short of the time: the time of the steps taken, which gives back exactly these steps.
    this.timeSeconds = reached ? s.timeSeconds : (sim.steps * sim.stepSeconds) / parameters.simSpeed;
    return reached;
  }

  /**
   * A simulation of `film` at its start. (Its programs compile in the frame of its first steps, not
   * with three's compileAsync: that one's polling outlives a lost context and queries the restored
   * one with names it no longer has.)
   */
  private make(film: FilmMade): void {
    this.simulation?.dispose();
    // The coarse start is drawn no more (the simulation draws its own start until it steps).
    this.preview?.dispose();
    this.preview = null;
    this.simulation = new GpuFilmSimulation(this.renderer, film.parameters, { renew: film.renew });
    this.film = film;
  }

  blow(point: Vec3, velocityMps: Vec3): void {
    const [x, y, z] = flowDirection(point);
    const r = Math.hypot(x, y, z);
    this.blowing = { center: [x / r, y / r, z / r], velocity: flowDirection(velocityMps), seconds: BLOW_FILM_SECONDS };
  }

  /**
   * Pricks the simulated film at the point (GpuFilmSimulation.puncture, whose reference is the
   * twin's punctureFilm): its rims, and with `renew` the new bubble, follow as after a rupture.
   * Nothing before the simulation is made (a new film's first frame shows its start on the coarse
   * grid, a film the simulation does not hold); a film started again from its start drops it.
   */
  burst(point: Vec3): void {
    this.simulation?.puncture(...flowDirection(point));
  }

  /** `count` steps, the first of them in the blow while it lasts. */
  private step(sim: GpuFilmSimulation, count: number): void {
    const b = this.blowing;
    if (!b || count <= 0) {
      sim.step(count);
      return;
    }
    const blown = Math.min(count, Math.ceil(b.seconds / sim.stepSeconds));
    sim.blow(b.center, b.velocity);
    sim.step(blown);
    sim.blow(b.center, CALM);
    sim.step(count - blown);
    b.seconds -= blown * sim.stepSeconds;
    if (b.seconds <= 0) this.blowing = null;
  }

  invalidate(): void {
    this.simulation?.invalidate();
    // The lost context's texture is let go, not disposed (three would delete it in the new context).
    this.preview = null;
  }

  dispose(): void {
    this.preview?.dispose();
    this.preview = null;
    this.simulation?.dispose();
    this.simulation = null;
    this.film = null;
  }
}

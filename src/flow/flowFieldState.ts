import type { WebGLRenderer } from 'three';
import { flowDirection, flowParametersOf } from '../fields/flowField.ts';
import type { FieldSettings, FieldState, FieldUniforms, Vec3 } from '../fields/thicknessField.ts';
import { GpuFilmSimulation } from './gpuFilmSimulation.ts';

/** Film seconds a blow lasts (a drag blows anew with each move). */
const BLOW_FILM_SECONDS = 0.05;
/** Still air. */
const CALM: Vec3 = [0, 0, 0];

/** A relative slack so that k·Δt film seconds take k steps despite rounding (the twin's advanceFilm's). */
const STEP_SLACK = 1e-9;

/**
 * The flow field's film (src/fields/flowField.ts) as the view keeps it: a GpuFilmSimulation of the
 * settings' parameters, advanced in whole fixed steps to the film time timeSeconds × simSpeed, so
 * the same settings give the same film on every load whatever the display rate; made anew from its
 * start when a parameter changes or the time goes back. With the settings' `renew` a new bubble
 * follows a burst (src/flow/renewFilm.ts).
 */
export class FlowFieldState implements FieldState {
  private simulation: GpuFilmSimulation | null = null;
  private key = '';
  /** The time shown, in the settings' seconds. */
  timeSeconds = 0;
  /** The blow the next steps take (the simulation's frame) and the film seconds it has left. */
  private blowing: { readonly center: Vec3; readonly velocity: Vec3; seconds: number } | null = null;

  constructor(private readonly renderer: WebGLRenderer) {}

  /** The simulation the film lives in now (null before the first advance). */
  get current(): GpuFilmSimulation | null {
    return this.simulation;
  }

  advance(u: FieldUniforms, s: FieldSettings, maxSteps: number): boolean {
    const parameters = flowParametersOf(s);
    const key = JSON.stringify([parameters, s.renew]);
    if (!this.simulation || key !== this.key) {
      this.simulation?.dispose();
      this.simulation = new GpuFilmSimulation(this.renderer, parameters, { renew: s.renew });
      this.key = key;
    }
    const sim = this.simulation;
    const wanted = Math.floor(((s.timeSeconds * s.simSpeed) / sim.stepSeconds) * (1 + STEP_SLACK));
    if (wanted < sim.steps) {
      // The film starts again: a blow still under way was on the film given up, not on its start.
      sim.reset();
      this.blowing = null;
    }
    this.step(sim, Math.min(wanted - sim.steps, maxSteps));
    u.uFlowFilm!.value = sim.paddedFilm;
    u.uFlowGridN!.value = sim.grid.n;
    const reached = sim.steps === wanted;
    // Short of the time: the time of the steps taken, which gives back exactly these steps.
    this.timeSeconds = reached ? s.timeSeconds : (sim.steps * sim.stepSeconds) / s.simSpeed;
    return reached;
  }

  blow(point: Vec3, velocityMps: Vec3): void {
    const [x, y, z] = flowDirection(point);
    const r = Math.hypot(x, y, z);
    this.blowing = { center: [x / r, y / r, z / r], velocity: flowDirection(velocityMps), seconds: BLOW_FILM_SECONDS };
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
  }

  dispose(): void {
    this.simulation?.dispose();
    this.simulation = null;
    this.key = '';
  }
}

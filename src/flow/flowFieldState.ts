import type { WebGLRenderer } from 'three';
import { flowParametersOf } from '../fields/flowField.ts';
import type { FieldSettings, FieldState, FieldUniforms } from '../fields/thicknessField.ts';
import { GpuFilmSimulation } from './gpuFilmSimulation.ts';

/** A relative slack so that k·Δt film seconds take k steps despite rounding (the twin's advanceFilm's). */
const STEP_SLACK = 1e-9;

/**
 * The flow field's film (src/fields/flowField.ts) as the view keeps it: a GpuFilmSimulation of the
 * settings' parameters, advanced in whole fixed steps to the film time timeSeconds × simSpeed, so
 * the same settings give the same film on every load whatever the display rate; made anew from its
 * start when a parameter changes or the time goes back.
 */
export class FlowFieldState implements FieldState {
  private simulation: GpuFilmSimulation | null = null;
  private key = '';
  /** The time shown, in the settings' seconds. */
  timeSeconds = 0;

  constructor(private readonly renderer: WebGLRenderer) {}

  /** The simulation now (null before the first advance): for tests and the benchmark. */
  get current(): GpuFilmSimulation | null {
    return this.simulation;
  }

  advance(u: FieldUniforms, s: FieldSettings, maxSteps: number): boolean {
    const parameters = flowParametersOf(s);
    const key = JSON.stringify(parameters);
    if (!this.simulation || key !== this.key) {
      this.simulation?.dispose();
      this.simulation = new GpuFilmSimulation(this.renderer, parameters);
      this.key = key;
    }
    const sim = this.simulation;
    const wanted = Math.floor(((s.timeSeconds * s.simSpeed) / sim.stepSeconds) * (1 + STEP_SLACK));
    if (wanted < sim.steps) sim.reset();
    sim.step(Math.min(wanted - sim.steps, maxSteps));
    u.uFlowFilm!.value = sim.paddedFilm;
    u.uFlowGridN!.value = sim.grid.n;
    const reached = sim.steps === wanted;
    // Short of the time: the time of the steps taken, which gives back exactly these steps.
    this.timeSeconds = reached ? s.timeSeconds : (sim.steps * sim.stepSeconds) / s.simSpeed;
    return reached;
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

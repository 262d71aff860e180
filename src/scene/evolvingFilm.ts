import type { WebGLRenderer } from 'three';
import { createFieldState } from '../bubble/fieldStates.ts';
import type { FieldName } from '../fields/fields.ts';
import type { FieldSettings, FieldUniforms, FieldState, Vec3 } from '../fields/thicknessField.ts';
import { FlowFieldState } from '../flow/flowFieldState.ts';
import type { GpuFilmSimulation } from '../flow/gpuFilmSimulation.ts';

/** Where `finish` reads its texel (the film's targets are RGBA float). */
const TEXEL = new Float32Array(4);

/** An evolving film as a frame drew it: the settings' time it shows (s), whether it is short of theirs, and a flowing film's grid, step and steps. */
export interface EvolvingFilmReading {
  readonly timeSeconds: number;
  readonly behind: boolean;
  readonly flow: { readonly gridN: number; readonly stepSeconds: number; readonly steps: number } | null;
}

/**
 * The simulation of a view's evolving film: made when a field whose film evolves is shown,
 * dropped when it is left (nothing for another field).
 */
export class EvolvingFilm {
  private current: { readonly field: FieldName; readonly state: FieldState } | null = null;
  /** Whether the last advance left the film short of the settings' time (more frames bring it there). */
  private behind = false;
  /**
   * Whether the last advance showed its film before its simulation, made the simulation or took its
   * first steps (which compile its programs): a frame whose cost is not the film's pace.
   */
  private settlingNow = false;
  /** The flowing film's simulation the last advance drew, and whether it has stepped. */
  private drawnSimulation: { readonly sim: GpuFilmSimulation | null; readonly stepped: boolean } | null = null;

  constructor(private readonly renderer: WebGLRenderer) {}

  /** Shows `field`: a new simulation where its film evolves and the field changed. */
  show(field: FieldName): void {
    if (this.current?.field === field) return;
    this.current?.state.dispose();
    const state = createFieldState(field, this.renderer);
    this.current = state && { field, state };
    this.behind = false;
    this.drawnSimulation = null;
  }

  /** The film as the last advance left it, or null for a field whose film does not evolve. */
  get reading(): EvolvingFilmReading | null {
    if (!this.current) return null;
    const sim = this.flowSimulation;
    const flow = sim && { gridN: sim.grid.n, stepSeconds: sim.stepSeconds, steps: sim.steps };
    return { timeSeconds: this.current.state.timeSeconds, behind: this.behind, flow };
  }

  /** Whether the last advance was the film's settling (a film shown before its simulation, or made, or its first steps). */
  get settling(): boolean {
    return this.settlingNow;
  }

  /** Waits for the flowing film's GPU work done so far (a one-texel read of its film; nothing for another field). */
  finish(): void {
    const sim = this.flowSimulation;
    if (sim) this.renderer.readRenderTargetPixels(sim.stateTargets.film, 0, 0, 1, 1, TEXEL);
  }

  /** Brings the film towards the settings' time by at most `maxSteps` steps (FieldState.advance); returns the steps taken. */
  advance(u: FieldUniforms, s: FieldSettings, maxSteps: number): number {
    if (!this.current) return 0;
    const before = this.stepsTaken;
    this.behind = !this.current.state.advance(u, s, maxSteps);
    const after = this.stepsTaken;
    // A film made anew or started again counts its steps from its start.
    const steps = after >= before ? after - before : after;
    this.settle(steps);
    return steps;
  }

  /** Whether this advance settled the film: no simulation drawn yet (the start shown first), a new one, or its first steps. */
  private settle(steps: number): void {
    const sim = this.flowSimulation;
    const last = this.drawnSimulation;
    const made = sim !== (last?.sim ?? null);
    const stepped = !made && (last?.stepped ?? false);
    this.settlingNow = this.flowState !== null && (sim === null || made || (!stepped && steps > 0));
    this.drawnSimulation = { sim, stepped: stepped || steps > 0 };
  }

  /** The flowing film's steps since its start (0 for another field). */
  private get stepsTaken(): number {
    return this.flowSimulation?.steps ?? 0;
  }

  /** The flowing film's simulation, if the field shown is the flow and it has been made. */
  private get flowSimulation(): GpuFilmSimulation | null {
    return this.flowState?.current ?? null;
  }

  /** The flowing film's state, if the field shown is the flow. */
  private get flowState(): FlowFieldState | null {
    const state = this.current?.state;
    return state instanceof FlowFieldState ? state : null;
  }

  /** Blows air on the film where it evolves and takes a blow (FieldState.blow); nothing for `null` (off the bubble). */
  blow(blown: { readonly point: Vec3; readonly velocityMps: Vec3 } | null): void {
    if (blown) this.current?.state.blow?.(blown.point, blown.velocityMps);
  }

  invalidate(): void {
    this.current?.state.invalidate();
  }

  dispose(): void {
    this.current?.state.dispose();
    this.current = null;
  }
}

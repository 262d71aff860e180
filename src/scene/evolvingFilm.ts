import type { WebGLRenderer } from 'three';
import { createFieldState } from '../bubble/fieldStates.ts';
import type { FieldName } from '../fields/fields.ts';
import type { FieldSettings, FieldUniforms, FieldState, Vec3 } from '../fields/thicknessField.ts';
import { FlowFieldState } from '../flow/flowFieldState.ts';
import type { GpuFilmSimulation } from '../flow/gpuFilmSimulation.ts';

/** Where `finish` reads its texel (the film's targets are RGBA float). */
const TEXEL = new Float32Array(4);

/**
 * The simulation of a view's evolving film: made when a field whose film evolves is shown,
 * dropped when it is left (nothing for another field).
 */
export class EvolvingFilm {
  private current: { readonly field: FieldName; readonly state: FieldState } | null = null;
  /** Whether the last advance left the film short of the settings' time (more frames bring it there). */
  behind = false;

  constructor(private readonly renderer: WebGLRenderer) {}

  /** Shows `field`: a new simulation where its film evolves and the field changed. */
  show(field: FieldName): void {
    if (this.current?.field === field) return;
    this.current?.state.dispose();
    const state = createFieldState(field, this.renderer);
    this.current = state && { field, state };
    this.behind = false;
  }

  /** The simulation, if the field shown evolves. */
  get state(): FieldState | null {
    return this.current?.state ?? null;
  }

  /** The settings' time (s) the film drawn shows (less than theirs while behind), or null for a field whose film does not evolve. */
  get timeSeconds(): number | null {
    return this.current?.state.timeSeconds ?? null;
  }

  /** Whether the last advance showed its film before its simulation, made the simulation or took its first steps (FieldState.settling): a frame whose cost is not the film's pace. */
  get settling(): boolean {
    return this.current?.state.settling ?? false;
  }

  /** The flowing film's grid (cells per cube face side) and step (film seconds) as simulated now, or null (no flowing film, or none simulated yet). */
  get flowGrid(): { readonly gridN: number; readonly stepSeconds: number } | null {
    const sim = this.flowSimulation;
    return sim && { gridN: sim.grid.n, stepSeconds: sim.stepSeconds };
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
    return after >= before ? after - before : after;
  }

  /** The flowing film's steps since its start (0 for another field). */
  private get stepsTaken(): number {
    return this.flowSimulation?.steps ?? 0;
  }

  /** The flowing film's simulation, if the field shown is the flow and it has been made. */
  private get flowSimulation(): GpuFilmSimulation | null {
    const state = this.current?.state;
    return state instanceof FlowFieldState ? state.current : null;
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

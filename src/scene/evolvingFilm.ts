import type { WebGLRenderer } from 'three';
import { createFieldState } from '../bubble/fieldStates.ts';
import type { FieldName, FieldSettings } from '../fields/fields.ts';
import type { FieldUniforms, FieldState, SimulationGrid, Vec3 } from '../fields/thicknessField.ts';

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

  /** The evolving film's grid and step as simulated now (FieldState.grid), or null (no evolving film, or none simulated yet). */
  get flowGrid(): SimulationGrid | null {
    return this.current?.state.grid ?? null;
  }

  /** Waits for the evolving film's GPU work done so far (FieldState.finish; nothing for another field). */
  finish(): void {
    this.current?.state.finish();
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

  /** The evolving film's steps since its start (0 for another field). */
  private get stepsTaken(): number {
    return this.current?.state.steps ?? 0;
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

import type { WebGLRenderer } from 'three';
import { createFieldState } from '../bubbleMaterials/fieldStates.ts';
import type { FieldDerived, FieldName, FieldSettings } from '../fields/fields.ts';
import type { FieldUniforms, FieldState, SimulationGrid, Vec3 } from '../fields/thicknessField.ts';

/** An evolving film as a frame drew it: the settings' time it shows (s), whether it is short of theirs, and its simulation's grid, step and steps (null before it is made). */
export interface EvolvingFilmReading {
  readonly timeSeconds: number;
  readonly behind: boolean;
  readonly flow: { readonly gridN: number; readonly stepSeconds: number; readonly steps: number } | null;
}

/**
 * The simulation of a view's evolving film: made when a field whose film evolves is shown,
 * dropped when it is left (nothing for another field). It reaches the simulation only through
 * the field's FieldState.
 */
export class EvolvingFilm {
  private current: { readonly field: FieldName; readonly state: FieldState<FieldDerived> } | null = null;
  /** Whether the last advance left the film short of the settings' time (more frames bring it there). */
  private behind = false;
  /**
   * Whether the last advance showed its film before its simulation, made the simulation or took its
   * first steps (which compile its programs): a frame whose cost is not the film's pace.
   */
  private settlingNow = false;
  /** The simulation the last advance drew (its grid: one object per simulation), and whether it has stepped. */
  private drawnSimulation: { readonly grid: SimulationGrid | null; readonly stepped: boolean } | null = null;

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
    const { grid, steps, timeSeconds } = this.current.state;
    return { timeSeconds, behind: this.behind, flow: grid && { ...grid, steps } };
  }

  /** Whether the last advance was the film's settling (a film shown before its simulation, or made, or its first steps). */
  get settling(): boolean {
    return this.settlingNow;
  }

  /** Waits for the evolving film's GPU work done so far (FieldState.finish; nothing for another field). */
  finish(): void {
    this.current?.state.finish();
  }

  /** Brings the film of the settings and of what its field derives of them (the frame's) towards the settings' time by at most `maxSteps` steps (FieldState.advance); returns the steps taken. */
  advance(u: FieldUniforms, s: FieldSettings, derived: FieldDerived, maxSteps: number): number {
    if (!this.current) return 0;
    const before = this.current.state.steps;
    this.behind = !this.current.state.advance(u, s, derived, maxSteps);
    const after = this.current.state.steps;
    // A film made anew or started again counts its steps from its start.
    const steps = after >= before ? after - before : after;
    this.settle(steps);
    return steps;
  }

  /** Whether this advance settled the film: no simulation drawn yet (the start shown first), a new one, or its first steps. */
  private settle(steps: number): void {
    const grid = this.current?.state.grid ?? null;
    const last = this.drawnSimulation;
    const made = grid !== (last?.grid ?? null);
    const stepped = !made && (last?.stepped ?? false);
    this.settlingNow = this.current !== null && (grid === null || made || (!stepped && steps > 0));
    this.drawnSimulation = { grid, stepped: stepped || steps > 0 };
  }

  /** Blows air on the film where it evolves and takes a blow (FieldState.blow); nothing for `null` (off the bubble). */
  blow(blown: { readonly point: Vec3; readonly velocityMps: Vec3 } | null): void {
    if (blown) this.current?.state.blow?.(blown.point, blown.velocityMps);
  }

  /** Bursts the film where it evolves and can burst (FieldState.burst); nothing for `null` (off the bubble). */
  burst(point: Vec3 | null): void {
    if (point) this.current?.state.burst?.(point);
  }

  invalidate(): void {
    this.current?.state.invalidate();
  }

  dispose(): void {
    this.current?.state.dispose();
    this.current = null;
  }
}

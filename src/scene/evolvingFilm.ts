import type { WebGLRenderer } from 'three';
import { createFieldState } from '../bubble/fieldStates.ts';
import type { FieldName } from '../fields/fields.ts';
import type { FieldSettings, FieldUniforms, FieldState, Vec3 } from '../fields/thicknessField.ts';

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

  /** Brings the film towards the settings' time by at most `maxSteps` steps (FieldState.advance). */
  advance(u: FieldUniforms, s: FieldSettings, maxSteps: number): void {
    if (this.current) this.behind = !this.current.state.advance(u, s, maxSteps);
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

import type { FlowParameters } from '../physics/flow/flowParameters.ts';

/** A point on the unit sphere, y up. */
export type Vec3 = readonly [number, number, number];

/**
 * The flowing film's own settings (field `flow`): bubble radius, Γ0, evaporation, wind and its turn, seed,
 * simulated seconds per second, grid (src/physics/flow/flowParameters.ts names them and holds their
 * ranges), and whether a new bubble follows a burst (the GPU's own, src/flow/renewFilm.ts).
 */
export const FLOW_SETTING_KEYS = [
  'radiusMm',
  'surfactantMolM2',
  'evaporationNmS',
  'windMps',
  'windTurnDegS',
  'seed',
  'simSpeed',
  'gridN',
  'renew',
] as const;

export type FlowSettings = Pick<FlowParameters, Exclude<(typeof FLOW_SETTING_KEYS)[number], 'renew'>> & { readonly renew: boolean };

/** What a field reads of the settings (the schema's rows in src/settings/filmParameters.ts). */
export interface FieldSettings extends FlowSettings {
  /** the mean thickness, nm */
  readonly thicknessNm: number;
  /** the drained film's top-to-bottom difference, nm */
  readonly thicknessRangeNm: number;
  readonly swirlSpeed: number;
  readonly timeSeconds: number;
}

/** A uniform of a field's shader, as three.js holds it. */
export type FieldUniforms = Record<string, { value: unknown }>;

/**
 * A film thickness field over the bubble: one TypeScript module and its GLSL twin (the same
 * name in shaders/fields/), registered once in src/fields/fields.ts. The module owns its
 * uniforms, their update per frame, its thickness lookup, the largest thickness it reaches (which
 * the film table must cover) and whether it changes with time.
 */
export interface ThicknessField {
  /** Its GLSL file, which defines `float tfcThicknessAt(vec3 p)` and declares the uniforms below. */
  readonly glsl: string;
  /** Its uniforms, with placeholder values. */
  readonly uniforms: () => FieldUniforms;
  /** Sets its uniforms to the settings (each frame). */
  readonly update: (u: FieldUniforms, s: FieldSettings) => void;
  /** The thickness in nm at `p` (the twin of its GLSL `tfcThicknessAt`; an evolving field's film at its start). */
  readonly thicknessAt: (p: Vec3, s: FieldSettings) => number;
  /** The largest thickness it reaches, in nm, at least 1 (the field is clamped to the domain's 20 µm). */
  readonly maxThicknessNm: (s: FieldSettings) => number;
  /**
   * The settings it reads (for its thickness, its uniforms, its simulation): a setting that some
   * field reads applies only under the fields that read it (the panel shows it only under those).
   */
  readonly reads: readonly (keyof FieldSettings)[];
  /** Whether it changes with time (the view animates only such a field). */
  readonly animates: boolean;
  /**
   * Whether its film evolves in a simulation the view holds (a FieldState, made for it in
   * src/bubble/fieldStates.ts) and advances to the settings' time before each frame.
   */
  readonly evolves?: true;
}

/** The simulation an evolving field's film lives in, kept by the view while it shows the field. */
export interface FieldState {
  /**
   * Brings the film to the settings' time by at most `maxSteps` fixed steps (from its start if its
   * parameters changed or the time went back) and points the uniforms at it; returns whether it
   * reached that time. Nothing runs when it is there already. With a finite `maxSteps` (an
   * animating app's frame) a film made anew is shown at its start first, its steps beginning in a
   * later frame; with Infinity (a frame that must show the time) it reaches the time.
   */
  advance(u: FieldUniforms, s: FieldSettings, maxSteps: number): boolean;
  /** The settings' time (s) its film shows: the last advance's, or less while the film is behind it. */
  readonly timeSeconds: number;
  /**
   * Blows air at a point of the bubble (unit, the view's frame, y up) with a velocity in m/s (its
   * part tangent there counts), over the film's next steps (a moment of film time): the film moves
   * only while it runs. A user's interaction, so not part of the settings (or of their reproducibility).
   */
  blow?(point: Vec3, velocityMps: Vec3): void;
  /** Makes its GPU objects anew after a lost context; the film starts again from its start. */
  invalidate(): void;
  dispose(): void;
}

import type { NumberDomain } from '../input/validate.ts';
import type { FieldSettings } from './fields.ts';

/** A point on the unit sphere, y up. */
export type Vec3 = readonly [number, number, number];

/**
 * A setting of a field's own, declared by the field: its name in the URL, its default and the
 * folder of the panel that shows it. src/settings/filmParameters.ts makes its row of the schema
 * (the label is the catalogues' `param.<key>`).
 */
interface OwnSetting<F extends string> {
  readonly url: string;
  readonly folder: F;
}
/** A number in a closed domain; the panel's slider moves in steps of `step` ('integer': a whole number). */
export interface NumberSetting<F extends string = string> extends OwnSetting<F> {
  readonly kind: 'number';
  readonly domain: NumberDomain;
  readonly defaultValue: number;
  readonly step: number | 'integer';
}
/** On or off. */
export interface FlagSetting<F extends string = string> extends OwnSetting<F> {
  readonly kind: 'flag';
  readonly defaultValue: boolean;
}
export type FieldSetting = NumberSetting | FlagSetting;
/** A field's own settings, by their settings key. */
export type FieldSettingRows = Readonly<Record<string, FieldSetting>>;

export const numberSetting = <F extends string>(
  url: string,
  domain: NumberDomain,
  defaultValue: number,
  step: number | 'integer',
  folder: F,
): NumberSetting<F> => ({ kind: 'number', url, domain, defaultValue, step, folder });

export const flagSetting = <F extends string>(url: string, defaultValue: boolean, folder: F): FlagSetting<F> => ({
  kind: 'flag',
  url,
  defaultValue,
  folder,
});

/** The values of settings declared by `R`. */
export type SettingValues<R> = { readonly [K in keyof R]: R[K] extends FlagSetting ? boolean : number };

/** The settings no one field owns, which a field may read (their rows: src/settings/filmParameters.ts). */
export interface SharedFieldSettings {
  /** the mean thickness, nm */
  readonly thicknessNm: number;
  /** the settings' time, s */
  readonly timeSeconds: number;
}

/** What a field with its own settings `R` reads: the shared settings and its own. */
export type FieldInput<R extends FieldSettingRows> = SharedFieldSettings & SettingValues<R>;
/** The same without the time: what a field derives and the range it reaches do not move with the clock (a frame only retimed keeps them). */
export type TimelessInput<R extends FieldSettingRows> = Omit<FieldInput<R>, 'timeSeconds'>;

/** A uniform of a field's shader, as three.js holds it. */
export type FieldUniforms = Record<string, { value: unknown }>;

/**
 * A field as a frame draws it (fields.ts's drawnField, once per frame): what the field derives of
 * the settings (its `derive`; null for a field that derives nothing) and the largest thickness it
 * reaches, which the film table covers. Its uniforms' update and its simulation take these.
 */
export interface DrawnField<D> {
  readonly derived: D;
  readonly maxThicknessNm: number;
}

/**
 * A film thickness field over the bubble: one TypeScript module and its GLSL twin (the same
 * name in shaders/fields/), registered once in src/fields/fields.ts. The module declares its own
 * settings (the schema's rows and the settings' members follow) and owns what it derives of them
 * once a frame, its uniforms, their update per frame, its thickness lookup, the largest thickness
 * it reaches (which the film table must cover), whether it changes with time and whether its film evolves.
 */
export interface ThicknessField<R extends FieldSettingRows, E extends boolean, D = null> {
  /** Its GLSL file, which defines `float tfcThicknessAt(vec3 p)` and declares the uniforms below. */
  readonly glsl: string;
  /**
   * Its own settings (a setting two fields share is one declaration both name): each applies only
   * under the fields that declare it (the panel shows it only under those).
   */
  readonly settings: R;
  /** The shared settings it reads (for its thickness, its uniforms, its simulation). */
  readonly reads: readonly (keyof SharedFieldSettings)[];
  /** Its uniforms, with placeholder values. */
  readonly uniforms: () => FieldUniforms;
  /**
   * What it derives of the settings, once for a frame (its range, its uniforms and its simulation
   * take it: the flowing film's parameters); none (null) if absent. It does not read the time.
   */
  readonly derive?: (s: TimelessInput<R>) => D;
  /** Sets its uniforms to the settings as the frame draws the field (each frame). */
  readonly update: (u: FieldUniforms, s: FieldInput<R>, drawn: DrawnField<D>) => void;
  /** The thickness in nm at `p` (the twin of its GLSL `tfcThicknessAt`; an evolving field's film at its start). */
  readonly thicknessAt: (p: Vec3, s: FieldInput<R>) => number;
  /** The largest thickness it reaches, in nm, at least 1 (the field is clamped to the domain's 20 µm). */
  readonly maxThicknessNm: (s: TimelessInput<R>, derived: D) => number;
  /** Whether it changes with time (the view animates only such a field). */
  readonly animates: boolean;
  /**
   * Whether its film evolves in a simulation the view holds (a FieldState, made for it by the table
   * of src/bubbleMaterials/fieldStates.ts, whose type asks one of each evolving field) and advances to the
   * settings' time before each frame.
   */
  readonly evolves: E;
}

/** A field as its module declares it: its settings' types follow from `settings`. */
export const thicknessField = <R extends FieldSettingRows, E extends boolean, D = null>(
  field: ThicknessField<R, E, D>,
): ThicknessField<R, E, D> => field;

/** The grid an evolving film is simulated on: cells per side (of a cube face) and the fixed step in film seconds. */
export interface SimulationGrid {
  readonly gridN: number;
  readonly stepSeconds: number;
}

/** The simulation an evolving field's film lives in, kept by the view while it shows the field; `D`: what the field derives of the settings (its `derive`). */
export interface FieldState<D = unknown> {
  /**
   * Brings the film of the settings and of what the field derives of them (`derived`, the
   * frame's) to the settings' time by at most `maxSteps` fixed steps (from its start if its
   * parameters changed or the time went back) and points the uniforms at it; returns whether it
   * reached that time. Nothing runs when it is there already. With a finite `maxSteps` (an
   * animating app's frame) a film made anew is shown at its start first, its steps beginning in a
   * later frame; with Infinity (a frame that must show the time) it reaches the time.
   */
  advance(u: FieldUniforms, s: FieldSettings, derived: D, maxSteps: number): boolean;
  /** The settings' time (s) its film shows: the last advance's, or less while the film is behind it. */
  readonly timeSeconds: number;
  /**
   * Blows air at a point of the bubble (unit, the view's frame, y up) with a velocity in m/s (its
   * part tangent there counts), over the film's next steps (a moment of film time): the film moves
   * only while it runs. A user's interaction, so not part of the settings (or of their reproducibility).
   */
  blow?(point: Vec3, velocityMps: Vec3): void;
  /**
   * Bursts the bubble at a point of it (the view's frame, y up; any length but 0): a hole opens
   * there and its rim runs outward as in a rupture of the film's own. A user's interaction, so not
   * part of the settings; the film bursts as it runs (a frozen one when its time moves on).
   */
  burst?(point: Vec3): void;
  /** Makes its GPU objects anew after a lost context; the film starts again from its start. */
  invalidate(): void;
  dispose(): void;
  /** The grid its film is simulated on now, or null before its simulation is made: one object per simulation, so a new object is a new simulation. */
  readonly grid: SimulationGrid | null;
  /** Its film's steps since its start (0 before its simulation is made). */
  readonly steps: number;
  /** Waits for its GPU work queued so far (a read of one texel of its film), so that a frame's cost includes it. */
  finish(): void;
}

import { type HdrEnvironment, STAND_IN_ENVIRONMENT, isHdrEnvironment } from '../environments/environments.ts';
import { type FieldDerived, THICKNESS_FIELDS, drawnField } from '../fields/fields.ts';
import type { DrawnField } from '../fields/thicknessField.ts';
import { methodReads } from '../methods/methods.ts';
import { type DrawnNotice, drawnFilmMethod } from '../settings/drawnFilm.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { AUTO } from '../settings/parameterRow.ts';
import { shownPixelRatio } from '../settings/pixelRatio.ts';
import { type ViewSettings, filmSettingsOf, governedValue } from '../settings/viewParameters.ts';

/** The light a film is drawn in. */
export type FilmLight = Pick<FilmSettings, 'illuminant' | 'lightTint' | 'normalization'>;

/** Where the HDR environment asked for stands: shown, on its way (the stand-in meanwhile), or failed (the stand-in instead). */
export type EnvironmentStatus =
  | { readonly state: 'shown' }
  | { readonly state: 'loading'; readonly env: HdrEnvironment }
  | { readonly state: 'failed'; readonly env: HdrEnvironment; readonly reason: string };

/** The frame governor's choice for the knobs the user left (src/app/frameBudget.ts, docs/governor.md). */
export interface GovernorChoice {
  readonly gridN: number;
  readonly stepsPerFrame: number;
  readonly pixelRatio: number;
}

/** What the machine and the page offer a frame. */
export interface FrameOffers {
  /** The frame governor's choice, or null: not governed (a frozen view). */
  readonly choice: GovernorChoice | null;
  /** Whether an HDR environment's map has arrived; why it failed to (null: it did not fail). */
  readonly environmentLoaded: (env: HdrEnvironment) => boolean;
  readonly environmentFailure: (env: HdrEnvironment) => string | null;
  /** Whether the GPU compiles programs without blocking the page (KHR_parallel_shader_compile). */
  readonly compilesInParallel: boolean;
  /** Whether a light's spectral transform, in the film's colour planes for `env` (filmPlanes), is at hand (asking starts it in a worker: src/film/spectralTransformTexture.ts). */
  readonly lightReady: (light: FilmLight & Partial<Pick<FilmSettings, 'env'>>) => boolean;
  /** The light of the frame drawn before (null: none drawn yet). */
  readonly lightShown: FilmLight | null;
  /** The device's pixels per CSS pixel. */
  readonly devicePixelRatio: number;
  /** Whether the canvas can show Display P3: asked only where a wide space is asked, as asking may reallocate the drawing buffer. */
  readonly drawsDisplayP3: () => boolean;
  /** The flowing film's steps per app frame where the governor does not choose them (the view's quality). */
  readonly baseStepsPerFrame: number;
}

/** Something drawn in place of what was asked: the setting, both values, and the line the page shows for it (null: none). */
export interface FrameNotice {
  readonly setting: 'mode' | 'env' | 'illuminant' | 'space' | 'gridN' | 'pixelRatio';
  readonly asked: string | number;
  readonly drawn: string | number;
  readonly message: DrawnNotice | null;
}

/** What a view draws for the settings asked, as the machine and the page offer it (resolveFrame). Immutable. */
export interface DrawnFrame {
  readonly asked: ViewSettings;
  /** The film's settings as drawn: the method, environment, light and governed knobs substituted where they must be. */
  readonly film: FilmSettings;
  /**
   * The film's field as drawn, derived once of `film`: what the field derives (the flowing film's
   * parameters, the governor's grid in them; null for a field that derives nothing), which its
   * uniforms and its simulation take, and the largest thickness it reaches: the film table's range.
   */
  readonly field: DrawnField<FieldDerived>;
  /** The drawing buffer's pixels per CSS pixel. */
  readonly pixelRatio: number;
  /** Whether the canvas shows Display P3: where a wide space (`display-p3`, `wide-gamut`) is asked and the canvas can; else sRGB. */
  readonly displayP3: boolean;
  /** The most steps the flowing film takes in an app frame (Infinity: all the time asks for). */
  readonly stepsPerFrame: number;
  /** Whether an app frame keeps the frame shown while the next one's programs compile (else it compiles them, blocking). */
  readonly keepsFrameWhileCompiling: boolean;
  readonly environment: EnvironmentStatus;
  /** The HDR environment whose map the view fetches now (null: none, or on its way already or failed). */
  readonly fetch: HdrEnvironment | null;
  /** The light asked for while its transform is computed (the film keeps the light shown); a frame that must show it computes it. */
  readonly lightPending: FilmLight | null;
  /** Each substitution, with why. */
  readonly notices: readonly FrameNotice[];
}

const lightOf = (s: FilmLight): FilmLight => ({ illuminant: s.illuminant, lightTint: s.lightTint, normalization: s.normalization });
const sameLight = (a: FilmLight, b: FilmLight): boolean => JSON.stringify(lightOf(a)) === JSON.stringify(lightOf(b));
const lightText = (l: FilmLight): string => JSON.stringify(lightOf(l));

/** The environment drawn: the one asked for, or the stand-in while its map is on its way or if it failed. */
function environmentOf(film: FilmSettings, o: FrameOffers): Pick<DrawnFrame, 'environment' | 'fetch'> & { notice: FrameNotice | null } {
  const env = film.env;
  if (!isHdrEnvironment(env) || o.environmentLoaded(env)) return { environment: { state: 'shown' }, fetch: null, notice: null };
  const reason = o.environmentFailure(env);
  const notice: FrameNotice = { setting: 'env', asked: env, drawn: STAND_IN_ENVIRONMENT, message: null };
  return reason === null
    ? { environment: { state: 'loading', env }, fetch: env, notice }
    : { environment: { state: 'failed', env, reason }, fetch: null, notice };
}

/** The light drawn: the one asked for, or for a method that reads its spectral transform the light shown until the new one's is at hand. */
function lightOfFrame(film: FilmSettings, o: FrameOffers): { light: FilmLight; pending: FilmLight | null; notice: FrameNotice | null } {
  const shown = o.lightShown;
  const waits = methodReads(film.mode, 'spectralTransform') && shown !== null && !sameLight(film, shown) && !o.lightReady(film);
  if (!waits) return { light: lightOf(film), pending: null, notice: null };
  return {
    light: shown,
    pending: lightOf(film),
    notice: { setting: 'illuminant', asked: lightText(film), drawn: lightText(shown), message: null },
  };
}

/** The governed knobs as drawn (viewParameters.ts): given, else the governor's choice, else a frozen view's defaults; a notice for each the governor or the device's cap decided. */
function governedOf(
  asked: ViewSettings,
  o: FrameOffers,
): { gridN: number; pixelRatio: number; stepsPerFrame: number; notices: FrameNotice[] } {
  const gridN = filmSettingsOf(asked, o.choice ? { gridN: o.choice.gridN } : {}).gridN;
  const pixelRatio = governedValue(asked.pixelRatio, o.choice?.pixelRatio, shownPixelRatio(o.devicePixelRatio));
  const stepsPerFrame = !o.choice ? o.baseStepsPerFrame : asked.simSpeed !== AUTO ? Infinity : o.choice.stepsPerFrame;
  const notices: FrameNotice[] = [];
  if (asked.gridN === AUTO && o.choice && THICKNESS_FIELDS[asked.field].evolves === true)
    notices.push({ setting: 'gridN', asked: AUTO, drawn: gridN, message: null });
  if (asked.pixelRatio === AUTO && pixelRatio !== (o.devicePixelRatio || 1))
    notices.push({ setting: 'pixelRatio', asked: AUTO, drawn: pixelRatio, message: null });
  return { gridN, pixelRatio, stepsPerFrame, notices };
}

/** The canvas's space: Display P3 where a wide space is asked and the canvas can show it, else sRGB (with a notice where a wide one was asked). */
function displayOf(film: FilmSettings, o: FrameOffers): { displayP3: boolean; notice: FrameNotice | null } {
  if (film.space === 'srgb') return { displayP3: false, notice: null };
  if (o.drawsDisplayP3()) return { displayP3: true, notice: null };
  return {
    displayP3: false,
    notice: { setting: 'space', asked: film.space, drawn: 'srgb', message: { key: 'app.noDisplayP3', values: {} } },
  };
}

/**
 * The one place where what is asked becomes what is drawn (docs/architecture.md#what-is-asked-and-what-is-drawn):
 * the method (drawnFilmMethod), the environment (the stand-in until its map arrives), the light
 * (the one shown until the new one's transform arrives), the canvas's space (sRGB where it cannot
 * show Display P3), the flowing film's grid, steps and the
 * pixel ratio (the governor's, or the device's within MAX_PIXEL_RATIO); and, derived once of the
 * film drawn, its field's values (the flow's parameters) and the table's range. A pure function of
 * the settings asked and the offers.
 */
export function resolveFrame(asked: ViewSettings, offers: FrameOffers): DrawnFrame {
  const governed = governedOf(asked, offers);
  const { film: withMethod, notice: methodNotice } = drawnFilmMethod({ ...filmSettingsOf(asked), gridN: governed.gridN }, 'view');
  const environment = environmentOf(withMethod, offers);
  const light = lightOfFrame(withMethod, offers);
  const film: FilmSettings = {
    ...withMethod,
    ...light.light,
    env: environment.environment.state === 'shown' ? withMethod.env : STAND_IN_ENVIRONMENT,
  };
  const display = displayOf(film, offers);
  const method: FrameNotice | null = methodNotice && { setting: 'mode', asked: asked.mode, drawn: film.mode, message: methodNotice };
  return Object.freeze({
    asked,
    film,
    field: Object.freeze(drawnField(film)),
    pixelRatio: governed.pixelRatio,
    displayP3: display.displayP3,
    stepsPerFrame: governed.stepsPerFrame,
    keepsFrameWhileCompiling: offers.compilesInParallel,
    environment: environment.environment,
    fetch: environment.fetch,
    lightPending: light.pending,
    notices: Object.freeze([method, environment.notice, light.notice, display.notice, ...governed.notices].filter((n) => n !== null)),
  });
}

/**
 * The frame at another time of the film: while the film animates, the time is all that moves from
 * frame to frame, and nothing else the frame resolved depends on it (a field's derived values and
 * range do not read it: TimelessInput), so the rest is kept as it is.
 */
export function retimed(frame: DrawnFrame, timeSeconds: number): DrawnFrame {
  return Object.freeze({ ...frame, asked: { ...frame.asked, timeSeconds }, film: { ...frame.film, timeSeconds } });
}

/** Whether two frames draw the same (each a plain, JSON-like value): a frame resolved again the same is not shown again. */
export const sameFrame = (a: DrawnFrame, b: DrawnFrame): boolean => a === b || JSON.stringify(a) === JSON.stringify(b);

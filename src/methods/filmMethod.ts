import type { MessageKey } from '../i18n/en.ts';
import type { FilmFill } from './filmFills.ts';
import type { FilmMediaOption } from './filmStacks.ts';

/**
 * What a method's shader reads beside TFC_FILM_MODE, each made for it by src/film/filmColor.ts:
 * - `polarization`: TFC_POLARIZATION;
 * - `media`: the media's defines and knots (a dispersive film or inside);
 * - `spectralBins`: the light's bin weights (a texture) and the bins' defines;
 * - `spectralTransform`: the light's spectral transform (a texture a worker computes) and the series' defines;
 * - `table`: the film table (built on the GPU when a parameter it depends on changes) and its layout;
 * - `stack`: a stack of films (each film's ñ per spectral bin and its thickness, a texture) and its defines.
 */
export type FilmMethodInput = 'polarization' | 'media' | 'spectralBins' | 'spectralTransform' | 'table' | 'stack';

/** What a method is asked to draw: the film's media or a stack of films (its fallback may depend on them). */
export type FilmMethodSettings = FilmMediaOption;

/** Another method drawn in a method's place, and the message that says why (with its `{marks}`). */
export interface DrawnInstead {
  readonly method: string;
  readonly notice: MessageKey;
  readonly values: Readonly<Record<string, string>>;
}

/** A cost against a table lookup's frame (1): with constant media, and with a film or inside whose index depends on λ. */
export interface FrameCost {
  readonly constant: number;
  readonly dispersive: number;
}

/**
 * A way to compute the film's colour on the GPU: one TypeScript module and its GLSL twin of the
 * same name (shaders/methods/), registered once in src/methods/methods.ts. Its label is the
 * message `choice.mode.<name>` in each catalogue.
 */
export interface FilmMethod {
  /** Its GLSL file, which defines `vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside)`. */
  readonly glsl: string;
  /** What its shader reads (the ingredients above). */
  readonly reads: readonly FilmMethodInput[];
  /** Whether a user may choose it (`mode=`); the others are the benchmark's peers. */
  readonly offered: boolean;
  /** The fills of the films it draws (filmFills.ts); the table is drawn in its place for the others. */
  readonly fills: readonly FilmFill[];
  /**
   * What its frame costs per fragment against a table lookup's, as the full benchmark measured it on
   * SwiftShader: what the benchmark's progress expects a row to take.
   */
  readonly frameCost: FrameCost;
}

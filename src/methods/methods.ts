import { exactMethod } from './exactMethod.ts';
import type { DrawnInstead, FilmMethod, FilmMethodInput, FilmMethodSettings } from './filmMethod.ts';
import { FILM_FILLS, type FilmFill, filmFill } from './filmFills.ts';
import { fourierMethod } from './fourierMethod.ts';
import { tableMethod } from './tableMethod.ts';
import { threeIridescenceMethod } from './threeIridescenceMethod.ts';

/**
 * Every way to compute the film's colour, by its name in the URL (`mode=`): the one place a method
 * is registered. The schema's choices, the shader's TFC_FILM_MODE and what each program reads
 * (defines, textures, the table) all come from here.
 */
export const FILM_METHOD_REGISTRY = {
  exact: exactMethod,
  table: tableMethod,
  fourier: fourierMethod,
  'three-iridescence': threeIridescenceMethod,
} as const satisfies Record<string, FilmMethod>;

export type FilmMethodName = keyof typeof FILM_METHOD_REGISTRY;
/** What a film shader can compute: every method. */
export const FILM_METHODS = Object.keys(FILM_METHOD_REGISTRY) as FilmMethodName[];

type Offered = { [K in FilmMethodName]: (typeof FILM_METHOD_REGISTRY)[K] extends { readonly offered: true } ? K : never }[FilmMethodName];
/** The methods a user may choose (`mode=`). */
export const MODES = FILM_METHODS.filter((name): name is Offered => FILM_METHOD_REGISTRY[name].offered);

/** Whether `method`'s shader reads `input` (filmMethod.ts names them). */
export const methodReads = (method: FilmMethodName, input: FilmMethodInput): boolean =>
  (FILM_METHOD_REGISTRY[method].reads as readonly FilmMethodInput[]).includes(input);

/** Whether `method` draws the film `s` itself (its fill is one of the method's), rather than the table in its place. */
export const supports = (method: FilmMethodName, s: FilmMethodSettings): boolean =>
  (FILM_METHOD_REGISTRY[method].fills as readonly FilmFill[]).includes(filmFill(s));

/** The method drawn for `s`: its own, or the table where it does not support the film's fill, with the notice saying why (null when none). */
export function drawnMethod(s: FilmMethodSettings & { readonly mode: FilmMethodName }): {
  readonly mode: FilmMethodName;
  readonly instead: DrawnInstead | null;
} {
  const insteadOf = FILM_FILLS[filmFill(s)].insteadOf;
  const instead = supports(s.mode, s) || insteadOf === null ? null : insteadOf(s, s.mode);
  return { mode: instead ? (instead.method as FilmMethodName) : s.mode, instead };
}

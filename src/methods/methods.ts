import { exactMethod } from './exactMethod.ts';
import type { FilmMethod, FilmMethodInput, FilmMethodSettings } from './filmMethod.ts';
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

/** The method drawn for `s`: its own, or the one its `drawnInstead` names, with the notice saying why (null when none). */
export function drawnMethod(s: FilmMethodSettings & { readonly mode: FilmMethodName }): {
  readonly mode: FilmMethodName;
  readonly instead: ReturnType<NonNullable<FilmMethod['drawnInstead']>>;
} {
  const method: FilmMethod = FILM_METHOD_REGISTRY[s.mode];
  const instead = method.drawnInstead?.(s) ?? null;
  return { mode: instead ? (instead.method as FilmMethodName) : s.mode, instead };
}

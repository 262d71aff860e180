import { exactMethod } from './exactMethod.ts';
import type { FilmMethod } from './filmMethod.ts';
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

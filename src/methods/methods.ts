import type { DrawnInstead, FilmMethodInput, FilmMethodSettings } from './filmMethod.ts';
import { FILM_FILLS, type FilmFill, filmFill } from './filmFills.ts';
import { FILM_METHOD_REGISTRY, type FilmMethodName } from './methodRegistry.ts';

export { FILM_METHOD_REGISTRY, FILM_METHODS, type FilmMethodName, MODES } from './methodRegistry.ts';

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

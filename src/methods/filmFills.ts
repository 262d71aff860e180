import { isDispersiveMedium, mediumText } from '../physics/medium.ts';
import type { DrawnInstead, FilmMethodInput, FilmMethodSettings } from './filmMethod.ts';
import { optionFilmsOf } from './filmStacks.ts';

/**
 * How a film is computed, by what it is: the one place that asks whether a film is a stack of
 * films given by the user's option or the one film of nFilm, and whether its media depend on λ. The
 * table's pass, the methods' inputs and which methods draw a film all follow from its fill:
 * - `constant`: one film whose media are the same at every λ: its Airy terms once (the table's
 *   series fill, `fourier`'s closed-form series, the binned integral's closed-form mean);
 * - `dispersive`: one film whose film or inside depends on λ: ñ per spectral bin from the media's
 *   knots (`media`);
 * - `stack`: the films the user's option stacks: the transfer-matrix recursion per bin, each
 *   film's ñ per bin from the stack's texture (`stack`).
 * `insteadOf` says what the table drawn in the place of a method that has no form for the fill tells
 * the user (null: every method has one).
 */
interface FilmFillEntry {
  readonly reads: readonly FilmMethodInput[];
  readonly insteadOf: ((s: FilmMethodSettings, method: string) => DrawnInstead) | null;
}

export const FILM_FILLS = {
  constant: { reads: [], insteadOf: null },
  dispersive: {
    reads: ['media'],
    insteadOf: (s) => {
      const name = isDispersiveMedium(s.nFilm) ? 'nFilm' : 'nInside';
      return { method: 'table', notice: 'app.fourierAsTable', values: { name, medium: mediumText(s[name]) } };
    },
  },
  stack: {
    reads: ['stack'],
    insteadOf: (s, method) => ({ method: 'table', notice: 'app.stackAsTable', values: { method, count: String(optionFilmsOf(s).length) } }),
  },
} as const satisfies Record<string, FilmFillEntry>;

export type FilmFill = keyof typeof FILM_FILLS;

/** The fill of a film: `stack` where its option stacks films, else `dispersive` or `constant` by its media. */
export function filmFill(s: FilmMethodSettings): FilmFill {
  if (optionFilmsOf(s).length > 0) return 'stack';
  return isDispersiveMedium(s.nFilm) || isDispersiveMedium(s.nInside) ? 'dispersive' : 'constant';
}

/** Whether a film's fill reads `input` (`media`: the media's knots per bin; `stack`: the stack's texture). */
export const fillReads = (s: FilmMethodSettings, input: 'media' | 'stack'): boolean =>
  (FILM_FILLS[filmFill(s)].reads as readonly FilmMethodInput[]).includes(input);

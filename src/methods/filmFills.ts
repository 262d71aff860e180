import type { MessageKey } from '../i18n/en.ts';
import { type IndexJson, indexJson, isDispersiveMedium, mediumIndexAt, mediumText } from '../physics/medium.ts';
import type { DrawnInstead, FilmMethodSettings } from './filmMethod.ts';
import { type FilmMediaOption, optionFilmsOf } from './filmStacks.ts';

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
 * Each entry declares what differs by the fill outside the methods too (src/film/filmFillGpu.ts holds
 * what differs on the GPU).
 */
interface FilmFillEntry {
  /** What the table drawn in the place of a method that has no form for the fill tells the user (null: every method has one). */
  readonly insteadOf: ((s: FilmMethodSettings, method: string) => DrawnInstead) | null;
  /** The media's settings it does not read: the panel hides them (a stack's films carry their own indices). */
  readonly unusedSettings: readonly (keyof FilmMediaOption)[];
  /** The notes it adds to the description of the film at the probe (src/plots/probeDescription.ts). */
  readonly probeNotes: (s: FilmMethodSettings) => readonly FillNote[];
  /** The film's indices the colour tool reports for a case at `wavelengthsNm` (src/cli/computeCaseColor.ts). */
  readonly caseIndices: (film: FilmMediaOption, wavelengthsNm: readonly number[]) => CaseIndices;
}

/** A message and its `{marks}`' values. */
export interface FillNote {
  readonly key: MessageKey;
  readonly values: Readonly<Record<string, string | number>>;
}

/** A case's film indices at its wavelengths: the one film's ñ_b (`nFilm`), or each film's of a stack from the outside in (`nLayers`). */
export interface CaseIndices {
  readonly nFilm?: readonly IndexJson[];
  readonly nLayers?: readonly (readonly IndexJson[])[];
}

/** A single film's entries: nFilm is its film, reported as such; no note. */
const SINGLE_FILM = {
  unusedSettings: [],
  probeNotes: () => [],
  caseIndices: (film: FilmMediaOption, wavelengthsNm: readonly number[]): CaseIndices => ({
    nFilm: wavelengthsNm.map((lambdaNm) => indexJson(mediumIndexAt(film.nFilm, lambdaNm))),
  }),
} as const satisfies Partial<FilmFillEntry>;

export const FILM_FILLS = {
  constant: { insteadOf: null, ...SINGLE_FILM },
  dispersive: {
    ...SINGLE_FILM,
    insteadOf: (s) => {
      const name = isDispersiveMedium(s.nFilm) ? 'nFilm' : 'nInside';
      return { method: 'table', notice: 'app.fourierAsTable', values: { name, medium: mediumText(s[name]) } };
    },
  },
  stack: {
    insteadOf: (s, method) => ({ method: 'table', notice: 'app.stackAsTable', values: { method, count: String(optionFilmsOf(s).length) } }),
    unusedSettings: ['nFilm'],
    probeNotes: (s) => [{ key: 'plots.stackNote', values: { count: optionFilmsOf(s).length } }],
    caseIndices: (film, wavelengthsNm) => ({
      nLayers: wavelengthsNm.map((lambdaNm) => optionFilmsOf(film).map((l) => indexJson(mediumIndexAt(l.n, lambdaNm)))),
    }),
  },
} as const satisfies Record<string, FilmFillEntry>;

export type FilmFill = keyof typeof FILM_FILLS;

/** The fill of a film: `stack` where its option stacks films, else `dispersive` or `constant` by its media. */
export function filmFill(s: FilmMethodSettings): FilmFill {
  if (optionFilmsOf(s).length > 0) return 'stack';
  return isDispersiveMedium(s.nFilm) || isDispersiveMedium(s.nInside) ? 'dispersive' : 'constant';
}

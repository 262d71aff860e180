import { FILM_STACK_DOMAIN } from './filmReflectance.ts';
import type { Medium } from './medium.ts';
import type { NumberDomain } from '../input/validate.ts';

/**
 * A stack of films (docs/physics.md#stacks-of-films): films from the outside in, each a medium
 * (anything a film takes: a number, `water`, a Cauchy film, a named medium, `complex:n,k`) and a
 * thickness. A layer whose thickness is FIELD_THICKNESS takes the thickness field's value where
 * the bubble is drawn, so the field can stretch the stack; the others keep theirs.
 */
export const FIELD_THICKNESS = 'd';

/** One layer of a stack as a user writes it. */
export interface FilmLayer {
  readonly n: Medium;
  /** nm within LAYERS_DOMAIN.thicknessNm, or FIELD_THICKNESS */
  readonly thicknessNm: number | typeof FIELD_THICKNESS;
}

/** One layer with its thickness known: FIELD_THICKNESS replaced by the field's value. */
export interface ResolvedLayer {
  readonly n: Medium;
  readonly thicknessNm: number;
}

/** The limits every entry point holds a stack to. */
export const LAYERS_DOMAIN = {
  /** Films after every `*N` is expanded. */
  count: { min: 1, max: 64, unit: 'films' },
  /** A layer's thickness: the single film's domain. */
  thicknessNm: FILM_STACK_DOMAIN.thicknessNm,
  /** The N of a group `(…)*N`. */
  repeat: { min: 1, max: 64, unit: '' },
} as const satisfies Record<string, NumberDomain>;

/** The films with every FIELD_THICKNESS film at `fieldThicknessNm`. */
export const resolveLayers = (films: readonly FilmLayer[], fieldThicknessNm: number): ResolvedLayer[] =>
  films.map(({ n, thicknessNm }) => ({ n, thicknessNm: thicknessNm === FIELD_THICKNESS ? fieldThicknessNm : thicknessNm }));

/** Whether any film takes the field's thickness (else the stack is the same everywhere on the bubble). */
export const followsField = (films: readonly FilmLayer[]): boolean => films.some((l) => l.thicknessNm === FIELD_THICKNESS);

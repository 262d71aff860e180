import { FIELD_THICKNESS, type FilmLayer, resolveLayers } from '../physics/stackFilms.ts';
import { type FilmStack, type Polarization, filmOptics, reflectanceAt } from '../physics/filmReflectance.ts';
import { layersXyz } from '../physics/stackColor.ts';
import { type Medium, isDispersiveMedium, mediumStackAt } from '../physics/medium.ts';
import { type ColorOptions, dispersiveReflectance, filmXyz } from '../physics/spectralIntegration.ts';
import { LAMBDA_MIN_NM, type Xyz } from '../physics/spectralWeights.ts';
import { type LayerStack, layersReflectance, layersReflectanceSpectrum } from '../physics/transferMatrix.ts';

/**
 * Every film is a stack of one or more films (LayerStack); one film is the paper's (FilmStack),
 * whose fast paths its float64 colour and R(λ) take here: the adaptive rule of the single film and
 * its optics computed once, bit for bit what the single film computes. Two or more films take the
 * transfer-matrix recursion (docs/physics.md#stacks-of-films). The user's option `layers` is read
 * here alone: what follows takes the films it gives.
 */

/** The media a film is asked for: nFilm and nInside, and the stack of films the `layers` option writes (none or empty: the one film of nFilm). */
export interface FilmMediaOption {
  readonly nFilm: Medium;
  readonly nInside: Medium;
  readonly layers?: readonly FilmLayer[];
}

/** A film as the settings and the colour tool's cases give it: the film of nFilm, or the stack its option writes. */
export type FilmOption = FilmStack<Medium> & FilmMediaOption;

/** The films a film's option stacks in place of the one film of nFilm: none where it gives none. */
export const optionFilmsOf = (film: Pick<FilmMediaOption, 'layers'>): readonly FilmLayer[] => film.layers ?? [];

/** A film's media with `films` as the films its option stacks (none: the one film of nFilm). */
export const withOptionFilms = <F extends Omit<FilmMediaOption, 'layers'>>(film: F, films: readonly FilmLayer[]): F & FilmMediaOption => ({
  ...film,
  layers: films,
});

/** A film's settings seen at θ_i = `angleDeg`, before the field's thickness is known: its media and the films its option stacks. */
export const filmOptionAt = (s: Omit<FilmOption, 'thicknessNm' | 'angleDeg'>, angleDeg: number): Omit<FilmOption, 'thicknessNm'> => ({
  nOutside: s.nOutside,
  nFilm: s.nFilm,
  nInside: s.nInside,
  layers: s.layers,
  angleDeg,
});

/**
 * The films a film's settings give, before the field's thickness is known: those of its option, or
 * (the option empty or absent) the one film of nFilm, which takes the field's thickness.
 */
export const filmLayersOf = (film: Omit<FilmMediaOption, 'nInside'>): readonly FilmLayer[] => {
  const films = optionFilmsOf(film);
  return films.length > 0 ? films : [{ n: film.nFilm, thicknessNm: FIELD_THICKNESS }];
};

/** The stack a film's settings give: filmLayersOf, every FIELD_THICKNESS film at thicknessNm, the field's thickness there. */
export const filmStackOf = (film: FilmOption): LayerStack => ({
  nOutside: film.nOutside,
  films: resolveLayers(filmLayersOf(film), film.thicknessNm),
  nInside: film.nInside,
  angleDeg: film.angleDeg,
});

/** The one film of a stack as the paper's (eqs 1–14), or null for two or more. */
export function singleFilmOf(stack: LayerStack): FilmStack<Medium> | null {
  if (stack.films.length !== 1) return null;
  const [{ n, thicknessNm }] = stack.films as [LayerStack['films'][number]];
  return { nOutside: stack.nOutside, nFilm: n, nInside: stack.nInside, thicknessNm, angleDeg: stack.angleDeg };
}

/** XYZ of the light the film reflects, eqs (15)–(18): filmXyz of one film, layersXyz of more. */
export function stackXyz(stack: LayerStack, options: ColorOptions = {}): Xyz {
  const film = singleFilmOf(stack);
  return film ? filmXyz(film, options) : layersXyz(stack, options);
}

/** R(λ) of the film: eqs (1)–(14) for one film (dispersiveReflectance), the transfer matrix for more. */
export function stackReflectance(lambdaNm: number, stack: LayerStack, polarization: Polarization = 'unpolarized'): number {
  const film = singleFilmOf(stack);
  return film ? dispersiveReflectance(lambdaNm, film, polarization) : layersReflectance(lambdaNm, stack, polarization);
}

/** R at each of a list of wavelengths (nm, > 0): one film's optics computed once where nothing depends on λ; the transfer matrix for more. */
export function stackReflectanceSpectrum(
  stack: LayerStack,
  lambdasNm: readonly number[],
  polarization: Polarization = 'unpolarized',
): number[] {
  const film = singleFilmOf(stack);
  if (!film) return layersReflectanceSpectrum(stack, lambdasNm, polarization);
  const dispersive = [film.nOutside, film.nFilm, film.nInside].some(isDispersiveMedium);
  const constantOptics = dispersive ? null : filmOptics(mediumStackAt(film, LAMBDA_MIN_NM), polarization);
  return lambdasNm.map((l) => reflectanceAt(constantOptics ?? filmOptics(mediumStackAt(film, l), polarization), l));
}

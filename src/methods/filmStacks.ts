import { FIELD_THICKNESS, type FilmLayer, resolveLayers } from '../physics/filmLayers.ts';
import { type FilmStack, type Polarization, filmOptics, reflectanceAt } from '../physics/filmReflectance.ts';
import { layersXyz } from '../physics/layersColor.ts';
import { type Medium, isDispersiveMedium, mediumStackAt } from '../physics/medium.ts';
import { type ColorOptions, dispersiveReflectance, filmXyz } from '../physics/spectralIntegration.ts';
import { LAMBDA_MIN_NM, type Xyz } from '../physics/spectralWeights.ts';
import { type LayerStack, layersReflectance, layersReflectanceSpectrum } from '../physics/transferMatrix.ts';

/**
 * Every film is a stack of one or more layers (LayerStack); one layer is the paper's film
 * (FilmStack), whose fast paths its float64 colour and R(λ) take here: the adaptive rule of the
 * single film and its optics computed once, bit for bit what the single film computes. Two or more
 * layers take the transfer-matrix recursion (docs/physics.md#stacks-of-films).
 */

/** A film as the settings and the colour tool's cases give it: the film of nFilm, or the stack the `layers` option writes. */
export type FilmOption = FilmStack<Medium> & { readonly layers?: readonly FilmLayer[] };

/**
 * The layers a film's settings give, before the field's thickness is known: those of its option, or
 * (the option empty or absent) the one layer of nFilm, which takes the field's thickness.
 */
export const filmLayersOf = (film: Pick<FilmOption, 'nFilm' | 'layers'>): readonly FilmLayer[] =>
  film.layers?.length ? film.layers : [{ n: film.nFilm, thicknessNm: FIELD_THICKNESS }];

/** The stack a film's settings give: filmLayersOf, every FIELD_THICKNESS layer at thicknessNm, the field's thickness there. */
export const filmStackOf = (film: FilmOption): LayerStack => ({
  nOutside: film.nOutside,
  layers: resolveLayers(filmLayersOf(film), film.thicknessNm),
  nInside: film.nInside,
  angleDeg: film.angleDeg,
});

/** The one layer of a stack as the paper's film (eqs 1–14), or null for two or more. */
export function singleFilmOf(stack: LayerStack): FilmStack<Medium> | null {
  if (stack.layers.length !== 1) return null;
  const [{ n, thicknessNm }] = stack.layers as [LayerStack['layers'][number]];
  return { nOutside: stack.nOutside, nFilm: n, nInside: stack.nInside, thicknessNm, angleDeg: stack.angleDeg };
}

/** XYZ of the light the film reflects, eqs (15)–(18): filmXyz of one layer, layersXyz of more. */
export function stackXyz(stack: LayerStack, options: ColorOptions = {}): Xyz {
  const film = singleFilmOf(stack);
  return film ? filmXyz(film, options) : layersXyz(stack, options);
}

/** R(λ) of the film: eqs (1)–(14) for one layer (dispersiveReflectance), the transfer matrix for more. */
export function stackReflectance(lambdaNm: number, stack: LayerStack, polarization: Polarization = 'unpolarized'): number {
  const film = singleFilmOf(stack);
  return film ? dispersiveReflectance(lambdaNm, film, polarization) : layersReflectance(lambdaNm, stack, polarization);
}

/** R at each of a list of wavelengths (nm, > 0): one layer's optics computed once where nothing depends on λ; the transfer matrix for more. */
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

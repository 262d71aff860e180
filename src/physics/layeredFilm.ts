import { type FilmLayer, resolveLayers } from './filmLayers.ts';
import { layersXyz } from './layersColor.ts';
import type { MediumStack } from './medium.ts';
import { type ColorOptions, filmXyz } from './spectralIntegration.ts';
import type { Xyz } from './spectralWeights.ts';
import type { LayerStack } from './transferMatrix.ts';

/**
 * A film as the view's `layers` setting and the colour tool's cases give it: the single film of
 * `nFilm` and `thicknessNm` or, when `layers` is non-empty, that stack of films on the film's
 * outside, inside and angle, with every FIELD_THICKNESS layer at `thicknessNm`, the field's
 * thickness there (docs/physics.md#stacks-of-films).
 */
export interface LayeredFilm extends MediumStack {
  /** From the outside in; empty or absent: the single film. */
  readonly layers?: readonly FilmLayer[];
}

/** The stack of films (its layers resolved at the film's thickness), or null for the single film. */
export function layerStackOf(film: LayeredFilm): LayerStack | null {
  if (!film.layers?.length) return null;
  return { nOutside: film.nOutside, layers: resolveLayers(film.layers, film.thicknessNm), nInside: film.nInside, angleDeg: film.angleDeg };
}

/** XYZ of the light the film reflects, eqs (15)–(18): filmXyz of the single film, layersXyz of a stack. */
export function layeredFilmXyz(film: LayeredFilm, options: ColorOptions): Xyz {
  const stack = layerStackOf(film);
  return stack ? layersXyz(stack, options) : filmXyz(film, options);
}

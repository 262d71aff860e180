import { type FilmLayer, resolveLayers } from '../physics/filmLayers.ts';
import { layersXyz } from '../physics/layersColor.ts';
import type { MediumStack } from '../physics/medium.ts';
import { type ColorOptions, filmXyz } from '../physics/spectralIntegration.ts';
import type { Xyz } from '../physics/spectralWeights.ts';
import type { LayerStack } from '../physics/transferMatrix.ts';

/**
 * The film at the probe as the plots take it: the single film of `nFilm` and `thicknessNm` or,
 * when `layers` is non-empty (the bubble's `layers` setting), that stack of films with every
 * FIELD_THICKNESS layer at `thicknessNm`, the field's thickness there (docs/physics.md#stacks-of-films).
 */
export interface PlottedFilm extends MediumStack {
  /** From the outside in; empty or absent: the single film. */
  readonly layers?: readonly FilmLayer[];
}

/** The stack the plots compute (the layers resolved at the probe's thickness), or null for the single film. */
export function layerStackOf(film: PlottedFilm): LayerStack | null {
  if (!film.layers?.length) return null;
  return { nOutside: film.nOutside, layers: resolveLayers(film.layers, film.thicknessNm), nInside: film.nInside, angleDeg: film.angleDeg };
}

/** XYZ of the light the film reflects, eqs (15)–(18): filmXyz of the single film, layersXyz of a stack. */
export function plottedXyz(film: PlottedFilm, options: ColorOptions): Xyz {
  const stack = layerStackOf(film);
  return stack ? layersXyz(stack, options) : filmXyz(film, options);
}

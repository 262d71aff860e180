import { asComplex } from '../physics/complex.ts';
import { type Polarization, filmOptics, reflectanceAt } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantSpd } from '../physics/illuminants.ts';
import { type MediumStack, isDispersiveMedium, mediumIndexAt, mediumStackAt } from '../physics/medium.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from '../physics/spectralWeights.ts';
import { layersReflectanceSpectrum } from '../physics/transferMatrix.ts';
import { type LayeredFilm, layerStackOf } from '../physics/layeredFilm.ts';

/** The spectra behind a film's colour, sampled over the integration range (eqs 15–18's integrand). */
export interface FilmSpectrum {
  readonly lambdasNm: Float64Array;
  /** R(λ), eqs (11)–(14), in [0, 1]. */
  readonly reflectance: Float64Array;
  /** I_in(λ), scaled so its largest value in the range is 1. */
  readonly incident: Float64Array;
  /** I_out(λ) = R(λ)·I_in(λ), on the same scale as `incident`. */
  readonly reflected: Float64Array;
  /** n_b(λ) (Re ñ_b) of a dispersive single film; null when the film's index is the same at every wavelength, and for a stack. */
  readonly filmIndex: Float64Array | null;
  /** The stack's layers (FIELD_THICKNESS resolved); 0 for the single film. */
  readonly layerCount: number;
}

/**
 * Samples R, I_in and I_out every `stepNm` from 380 to 830 nm: R of the single film (eqs 11–14),
 * or of the stack of `stack.layers` (the transfer matrix) when there is one.
 */
export function filmSpectrum(stack: LayeredFilm, illuminant: IlluminantSpec, polarization: Polarization, stepNm = 1): FilmSpectrum {
  const count = Math.floor((LAMBDA_MAX_NM - LAMBDA_MIN_NM) / stepNm) + 1;
  const lambdasNm = Float64Array.from({ length: count }, (_, i) => LAMBDA_MIN_NM + i * stepNm);
  const layers = layerStackOf(stack);
  const reflectance = layers
    ? Float64Array.from(layersReflectanceSpectrum(layers, Array.from(lambdasNm), polarization))
    : singleFilmReflectance(stack, lambdasNm, polarization);
  const filmIndex = !layers && isDispersiveMedium(stack.nFilm) ? lambdasNm.map((l) => asComplex(mediumIndexAt(stack.nFilm, l)).re) : null;
  const spd = illuminantSpd(illuminant);
  const incident = lambdasNm.map(spd);
  const peak = Math.max(...incident);
  const reflected = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    incident[i]! /= peak;
    reflected[i] = reflectance[i]! * incident[i]!;
  }
  return { lambdasNm, reflectance, incident, reflected, filmIndex, layerCount: layers?.layers.length ?? 0 };
}

/** R of the single film at each wavelength, its optics computed once when nothing depends on λ. */
function singleFilmReflectance(stack: MediumStack, lambdasNm: Float64Array, polarization: Polarization): Float64Array {
  const dispersive = isDispersiveMedium(stack.nFilm) || isDispersiveMedium(stack.nInside);
  const constantOptics = dispersive ? null : filmOptics(mediumStackAt(stack, LAMBDA_MIN_NM), polarization);
  return lambdasNm.map((l) => reflectanceAt(constantOptics ?? filmOptics(mediumStackAt(stack, l), polarization), l));
}

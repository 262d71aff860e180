import { asComplex } from '../physics/complex.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantDrawn } from '../physics/illuminants.ts';
import { type LightTint, WHITE_TINT } from '../physics/lightTint.ts';
import { isDispersiveMedium, mediumIndexAt } from '../physics/medium.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from '../physics/spectralWeights.ts';
import { type FilmOption, filmStackOf, optionFilmsOf, singleFilmOf, stackReflectanceSpectrum } from '../methods/filmStacks.ts';

/** The spectra behind a film's colour, sampled over the integration range (eqs 15–18's integrand). */
export interface FilmSpectrum {
  readonly lambdasNm: Float64Array;
  /** R(λ), eqs (11)–(14), in [0, 1]. */
  readonly reflectance: Float64Array;
  /** I_in(λ) of the tinted light, scaled so its largest value in the range is 1 (a line source's lines as illuminantDrawn draws them). */
  readonly incident: Float64Array;
  /** I_out(λ) = R(λ)·I_in(λ), on the same scale as `incident`. */
  readonly reflected: Float64Array;
  /** n_b(λ) (Re ñ_b) of a dispersive single film; null when its index is the same at every wavelength, and for a stack of two or more films. */
  readonly filmIndex: Float64Array | null;
  /** The films the film's option stacks; 0 for the film of nFilm. */
  readonly layerCount: number;
}

/**
 * Samples R, I_in and I_out every `stepNm` from 380 to 830 nm: R of the film's stack (filmStackOf:
 * eqs 11–14 for one film, the transfer matrix for more), I_in of the illuminant with its tint.
 */
export function filmSpectrum(
  film: FilmOption,
  illuminant: IlluminantSpec,
  polarization: Polarization,
  stepNm = 1,
  lightTint: LightTint = WHITE_TINT,
): FilmSpectrum {
  const count = Math.floor((LAMBDA_MAX_NM - LAMBDA_MIN_NM) / stepNm) + 1;
  const lambdasNm = Float64Array.from({ length: count }, (_, i) => LAMBDA_MIN_NM + i * stepNm);
  const stack = filmStackOf(film);
  const reflectance = Float64Array.from(stackReflectanceSpectrum(stack, Array.from(lambdasNm), polarization));
  const single = singleFilmOf(stack);
  const filmIndex = single && isDispersiveMedium(single.nFilm) ? lambdasNm.map((l) => asComplex(mediumIndexAt(single.nFilm, l)).re) : null;
  const incident = lambdasNm.map(illuminantDrawn(illuminant, lightTint));
  const peak = Math.max(...incident);
  const reflected = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    incident[i]! /= peak;
    reflected[i] = reflectance[i]! * incident[i]!;
  }
  return { lambdasNm, reflectance, incident, reflected, filmIndex, layerCount: optionFilmsOf(film).length };
}

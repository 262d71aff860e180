import { asComplex } from '../physics/complex.ts';
import { type Polarization, filmOptics, reflectanceAt } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantSpd } from '../physics/illuminants.ts';
import { type MediumStack, isDispersiveMedium, mediumIndexAt, mediumStackAt } from '../physics/medium.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from '../physics/spectralWeights.ts';

/** The spectra behind a film's colour, sampled over the integration range (eqs 15–18's integrand). */
export interface FilmSpectrum {
  readonly lambdasNm: Float64Array;
  /** R(λ), eqs (11)–(14), in [0, 1]. */
  readonly reflectance: Float64Array;
  /** I_in(λ), scaled so its largest value in the range is 1. */
  readonly incident: Float64Array;
  /** I_out(λ) = R(λ)·I_in(λ), on the same scale as `incident`. */
  readonly reflected: Float64Array;
  /** n_b(λ) (Re ñ_b) of a dispersive film; null when the film's index is the same at every wavelength. */
  readonly filmIndex: Float64Array | null;
}

/** Samples R, I_in and I_out every `stepNm` from 380 to 830 nm. */
export function filmSpectrum(stack: MediumStack, illuminant: IlluminantSpec, polarization: Polarization, stepNm = 1): FilmSpectrum {
  const count = Math.floor((LAMBDA_MAX_NM - LAMBDA_MIN_NM) / stepNm) + 1;
  const dispersive = isDispersiveMedium(stack.nFilm) || isDispersiveMedium(stack.nInside);
  const constantOptics = dispersive ? null : filmOptics(mediumStackAt(stack, LAMBDA_MIN_NM), polarization);
  const filmIndex = isDispersiveMedium(stack.nFilm) ? new Float64Array(count) : null;
  const spd = illuminantSpd(illuminant);
  const lambdasNm = new Float64Array(count);
  const reflectance = new Float64Array(count);
  const incident = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    const l = LAMBDA_MIN_NM + i * stepNm;
    lambdasNm[i] = l;
    reflectance[i] = reflectanceAt(constantOptics ?? filmOptics(mediumStackAt(stack, l), polarization), l);
    if (filmIndex) filmIndex[i] = asComplex(mediumIndexAt(stack.nFilm, l)).re;
    incident[i] = spd(l);
  }
  const peak = Math.max(...incident);
  const reflected = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    incident[i]! /= peak;
    reflected[i] = reflectance[i]! * incident[i]!;
  }
  return { lambdasNm, reflectance, incident, reflected, filmIndex };
}

import { type MeshPhysicalMaterial } from 'three';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { type Medium } from '../physics/medium.ts';
import { type NumberDomain, assertInRange, expectedNumber, isInDomain } from '../input/validate.ts';
import { type CheckedOptions } from './spectralIridescenceOptions.ts';

/** A parameter's value within its domain: as given, or refused (a ParameterError), or clamped to it. */
export type Limit = (name: string, value: number, d: NumberDomain) => number;

/** Where a parameter is given (outside three's render): a value out of its domain is a ParameterError naming it. */
export const refuse: Limit = (name, value, d) => {
  assertInRange(name, value, d.min, d.max, d.unit);
  return value;
};

/**
 * Where a parameter is drawn (inside three's render, which must not throw): a value out of its
 * domain is clamped to it (NaN to its lower end), and `warn` is told which parameter and why.
 */
export const clampWithWarning =
  (warn: (name: string, message: string) => void): Limit =>
  (name, value, d) => {
    if (isInDomain(value, d)) return value;
    const clamped = Number.isNaN(value) ? d.min : Math.min(d.max, Math.max(d.min, value));
    warn(name, `${name} ${String(value)} is not allowed; expected ${expectedNumber(d)}; drawn with ${clamped}`);
    return clamped;
  };

/** Whether the film lies on a metal made from the base colour (materialFilm.ts's metalOf): the material is a metal and names no base. */
export const onColourMetal = (m: MeshPhysicalMaterial, o: CheckedOptions): boolean => o.base === null && m.metalness > 0;

/** The parameters of three's the film reads, each held to the film stack's domain by `limit`, which names three's property. */
export interface FilmParameters {
  /** the film: `film`, or iridescenceIOR */
  readonly nFilm: Medium;
  /** what lies under it: `base`; null over a metal from the base colour; else three's ior */
  readonly nInside: Medium | null;
  /** the thickness range's larger end */
  readonly thicknessNm: number;
}

/** A physical material's parameters the film reads (FilmParameters), each held to the film stack's domain by `limit`. */
export function filmParametersOf(m: MeshPhysicalMaterial, o: CheckedOptions, limit: Limit): FilmParameters {
  const d = FILM_STACK_DOMAIN;
  const nFilm = o.film ?? limit('iridescenceIOR', m.iridescenceIOR, d.nFilm);
  const nInside = o.base ?? (onColourMetal(m, o) ? null : limit('ior', m.ior, d.nInside));
  const minNm = limit('iridescenceThicknessMinimum', m.iridescenceThicknessMinimum, d.thicknessNm);
  const maxNm = limit('iridescenceThicknessMaximum', m.iridescenceThicknessMaximum, d.thicknessNm);
  return { nFilm, nInside, thicknessNm: Math.max(minNm, maxNm) };
}

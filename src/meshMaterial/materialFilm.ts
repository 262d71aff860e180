import { type MeshPhysicalMaterial } from 'three';
import { type LinearRgb, artistMetalMedium } from '../physics/artistMetal.ts';
import { FILM_STACK_DOMAIN, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { type Medium, absorbsInBand } from '../physics/medium.ts';
import { type SampledIndex } from '../physics/sampledIndex.ts';
import { type NumberDomain, assertInRange, expectedNumber, isInDomain } from '../input/validate.ts';
import { filmColorDefines } from '../film/filmColor.ts';
import { type FilmOptics } from '../settings/filmSettings.ts';
import { drawnFilmMethod } from '../settings/drawnFilm.ts';
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

/** The film a material draws: its optics, and the thickness its table reaches. */
export type MaterialFilmSettings = FilmOptics & { readonly thicknessNm: number };

/**
 * The film as the demo's settings describe it, from a physical material's glTF parameters: the
 * film (`film`, or iridescenceIOR) in air over the base (`base`, the metal of the base colour, or
 * ior), up to the thickness range's larger end. Each of three's parameters is held to the film
 * stack's domain by `limit`, which names three's property.
 */
export function filmSettingsOf(m: MeshPhysicalMaterial, o: CheckedOptions, limit: Limit): MaterialFilmSettings {
  const d = FILM_STACK_DOMAIN;
  const nFilm = o.film ?? limit('iridescenceIOR', m.iridescenceIOR, d.nFilm);
  const nInside = baseOf(m, o) ?? limit('ior', m.ior, d.nInside);
  const minNm = limit('iridescenceThicknessMinimum', m.iridescenceThicknessMinimum, d.thicknessNm);
  const maxNm = limit('iridescenceThicknessMaximum', m.iridescenceThicknessMaximum, d.thicknessNm);
  const { illuminant, polarization, normalization, layers } = o;
  const nOutside = SOAP_FILM_IN_AIR.nOutside;
  return {
    illuminant,
    polarization,
    normalization,
    layers,
    mode: drawnModeOf(o),
    thicknessNm: Math.max(minNm, maxNm),
    nOutside,
    nFilm,
    nInside,
  };
}

/** The method drawn: the option's, or where it has no form for the film (a stack in `fourier`) the one drawn in its place (drawnFilmMethod). */
const drawnModeOf = (o: CheckedOptions): CheckedOptions['mode'] =>
  drawnFilmMethod({ ...o, nFilm: o.film ?? SOAP_FILM_IN_AIR.nFilm, nInside: o.base ?? SOAP_FILM_IN_AIR.nInside }, 'material').film.mode;

/** Each material's metal from its colours, and the colours it was made from. */
const metals = new WeakMap<MeshPhysicalMaterial, { readonly key: string; readonly medium: SampledIndex }>();

/**
 * The metal under the film when the material is one and names no base: its index from the base
 * colour (F0) and the edge tint (by default the base colour), per channel (artistMetal.ts).
 */
export function metalOf(m: MeshPhysicalMaterial, o: CheckedOptions): SampledIndex | null {
  if (o.base !== null || !(m.metalness > 0)) return null;
  const color: LinearRgb = [m.color.r, m.color.g, m.color.b];
  const tint = o.edgeTint ?? color;
  // Asked for on every draw (the settings, the program key): made again only when a colour changes.
  const key = `${color.join()} ${tint.join()}`;
  const made = metals.get(m);
  if (made?.key === key) return made.medium;
  const medium = artistMetalMedium(color, tint);
  metals.set(m, { key, medium });
  return medium;
}

/** What lies under the film in place of three's ior: `base`, or the metal from the base colour, or null. */
const baseOf = (m: MeshPhysicalMaterial, o: CheckedOptions): Medium | null => o.base ?? metalOf(m, o);

/**
 * The GLSL defines of the film (filmColor.glsl's, for the mode). The film is `film` (a medium) or
 * three's iridescenceIOR, a number; the base is `base` (a medium), the metal, or three's ior, a number.
 */
export const filmDefinesOf = (m: MeshPhysicalMaterial, o: CheckedOptions): Record<string, number> =>
  filmColorDefines(
    { ...o, mode: drawnModeOf(o), nFilm: o.film ?? SOAP_FILM_IN_AIR.nFilm, nInside: baseOf(m, o) ?? SOAP_FILM_IN_AIR.nInside },
    o.quality,
  );

/** What of the program the material's metalness and colour decide: whether the lobe is the metallic one, and over an opaque metal. */
export function metalStateOf(m: MeshPhysicalMaterial, o: CheckedOptions): string {
  const metal = metalOf(m, o);
  return metal === null ? '' : absorbsInBand(metal) ? ' metallic' : ' metallic clear';
}

/** The film's part of the program key: the defines, and which lobe is spectral. */
export const filmKeyOf = (m: MeshPhysicalMaterial, o: CheckedOptions): string =>
  `${JSON.stringify(filmDefinesOf(m, o))}${metalStateOf(m, o)}`;

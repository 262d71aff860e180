import { type MeshPhysicalMaterial } from 'three';
import { type LinearRgb, artistMetalMedium } from '../physics/artistMetal.ts';
import { SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { type Medium, absorbsInBand } from '../physics/medium.ts';
import { type SampledIndex } from '../physics/sampledIndex.ts';
import { filmColorDefines } from '../film/filmColor.ts';
import { type FilmOptics } from '../settings/filmSettings.ts';
import { drawnFilmMethod } from '../settings/drawnFilm.ts';
import type { MessageKey } from '../i18n/en.ts';
import { type CheckedOptions } from './spectralIridescenceOptions.ts';
import { type Limit, clampWithWarning, filmParametersOf, onColourMetal } from './materialParameters.ts';
import { type SpectralFilm, filmOf, warnOnce } from './spectralFilm.ts';

/** The film a material draws: its optics, and the thickness its table reaches. */
export type MaterialFilmSettings = FilmOptics & { readonly thicknessNm: number };

/**
 * The film as the demo's settings describe it, from a physical material's glTF parameters: the
 * film (`film`, or iridescenceIOR) in air over the base (`base`, the metal of the base colour, or
 * ior), up to the thickness range's larger end. Each of three's parameters is held to the film
 * stack's domain by `limit`, which names three's property.
 */
export function filmSettingsOf(m: MeshPhysicalMaterial, o: CheckedOptions, limit: Limit): MaterialFilmSettings {
  const { nFilm, nInside, thicknessNm } = filmParametersOf(m, o, limit);
  const { illuminant, lightTint, polarization, normalization, layers } = o;
  const nOutside = SOAP_FILM_IN_AIR.nOutside;
  return {
    illuminant,
    lightTint,
    polarization,
    normalization,
    layers,
    mode: drawnModeOf(o),
    thicknessNm,
    nOutside,
    nFilm,
    nInside: nInside ?? metalOf(m, o)!,
  };
}

/**
 * The method drawn and why: the option's, or where it has no form for the film (a stack in
 * `fourier`) or cannot hold the light (a line source in a table) the one drawn in its place (drawnFilmMethod).
 */
const drawnMethodOf = (o: CheckedOptions) =>
  drawnFilmMethod({ ...o, nFilm: o.film ?? SOAP_FILM_IN_AIR.nFilm, nInside: o.base ?? SOAP_FILM_IN_AIR.nInside }, 'material');

const drawnModeOf = (o: CheckedOptions): CheckedOptions['mode'] => drawnMethodOf(o).film.mode;

/** Why a method is drawn in another's place, in the material's console warning (the entries load no message catalogue). */
const insteadReason = (key: MessageKey): string =>
  key === 'app.linesAsExact' ? "a table's grid cannot hold a line source's fringes" : 'it has no closed form for a stack of films';

/** Each material's metal from its colours, and the colours it was made from. */
const metals = new WeakMap<MeshPhysicalMaterial, { readonly key: string; readonly medium: SampledIndex }>();

/**
 * The metal under the film when the material is one and names no base: its index from the base
 * colour (F0) and the edge tint (by default the base colour), per channel (artistMetal.ts).
 */
export function metalOf(m: MeshPhysicalMaterial, o: CheckedOptions): SampledIndex | null {
  if (!onColourMetal(m, o)) return null;
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

/** Whether the film of `m` was last drawn in a scene with an environment (SpectralFilm.sceneEnvironment). */
const sceneEnvironmentOf = (m: MeshPhysicalMaterial): boolean => filmOf(m)?.sceneEnvironment ?? false;

/**
 * The GLSL defines of the film (filmColor.glsl's, for the mode and its colour planes). The film is
 * `film` (a medium) or three's iridescenceIOR, a number; the base is `base` (a medium), the metal,
 * or three's ior, a number.
 */
export const filmDefinesOf = (m: MeshPhysicalMaterial, o: CheckedOptions): Record<string, number> =>
  filmColorDefines(
    {
      ...o,
      mode: drawnModeOf(o),
      nFilm: o.film ?? SOAP_FILM_IN_AIR.nFilm,
      nInside: baseOf(m, o) ?? SOAP_FILM_IN_AIR.nInside,
      sceneEnvironment: sceneEnvironmentOf(m),
    },
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

/**
 * The film as both entries draw it now, inside three's render (which must not throw): a parameter
 * out of its domain clamped, with a warning; where the method cannot draw the film or its light,
 * the one drawn in its place, said once. `o`: the options drawn (the film's, unless a program
 * still draws the ones it was built for).
 */
export function drawnFilmSettings(m: MeshPhysicalMaterial, film: SpectralFilm, o: CheckedOptions = film.options): MaterialFilmSettings {
  const s = filmSettingsOf(
    m,
    o,
    clampWithWarning((name, message) => warnOnce(film, name, message)),
  );
  const { notice } = drawnMethodOf(o);
  if (notice) warnOnce(film, notice.key, `mode ${o.mode}: ${insteadReason(notice.key)}; drawn with mode ${s.mode}`);
  return { ...s, sceneEnvironment: film.sceneEnvironment };
}

/**
 * Follows the scene's environment from draw to draw (`environment`: the one three lights the
 * material with, its envMap or the scene's): its coming or going changes the film's colour planes,
 * and so its program.
 */
export function followEnvironment(m: MeshPhysicalMaterial, film: SpectralFilm, environment: unknown): void {
  const has = environment !== null && environment !== undefined;
  if (film.sceneEnvironment !== has) m.needsUpdate = true;
  film.sceneEnvironment = has;
}

/**
 * Follows the material's metal from draw to draw: metalness and colour are uniforms to three, so a
 * metal's coming or going (or its k reaching 0) moves the version for a program three would not make.
 */
export function followMetal(m: MeshPhysicalMaterial, film: SpectralFilm): void {
  const state = metalStateOf(m, film.options);
  if (film.drawnMetal !== null && film.drawnMetal !== state) m.needsUpdate = true;
  film.drawnMetal = state;
}

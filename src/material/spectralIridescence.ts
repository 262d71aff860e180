import {
  Material,
  type MeshPhysicalMaterial,
  type Object3D,
  ShaderChunk,
  type WebGLProgramParametersWithUniforms,
  type WebGLRenderer,
} from 'three';
import { type LinearRgb, artistMetalMedium } from '../physics/artistMetal.ts';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { type Medium, absorbsInBand } from '../physics/medium.ts';
import { type SampledIndex } from '../physics/sampledIndex.ts';
import { type NumberDomain, assertInRange, expectedNumber, isInDomain } from '../physics/validate.ts';
import { filmColorDefines, filmColorUniforms, releaseFilmColorTextures, updateFilmColorUniforms } from '../film/filmColor.ts';
import { DEFAULT_SETTINGS } from '../settings/filmParameters.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { type FilmSettings } from '../settings/filmSettings.ts';
import { FilmTable, tableKey } from '../film/filmTable.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import {
  type CheckedOptions,
  OPTION_NAMES,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from './spectralIridescenceOptions.ts';
import { restoresOf } from './contextRestores.ts';

/** The call in three's lights_fragment_begin chunk that gives the film over the dielectric base. */
const DIELECTRIC_FILM = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor )';
const SPECTRAL_FILM = 'tfcSpectralIridescence( material.iridescenceThickness, dotNVi )';
/** The call that gives the film over the metallic base (three's base colour as F0, Schlick's Fresnel). */
const METALLIC_FILM = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor )';
/**
 * three's F0 for the film's image-based light: Schlick's curve inverted at n·v. Ours inverts the
 * lobe the light is then integrated with, its DFG table's single scattering and three's multiple
 * scattering (docs/material.md#the-films-f0-for-image-based-light), so under uniform light the
 * surface reflects the film's own value at n·v at every angle.
 */
const DIELECTRIC_F0 = 'material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );';
const SPECTRAL_F0 = (lobe: 'Dielectric' | 'Metallic') =>
  `material.iridescenceF0${lobe} = tfcSpectralIridescenceF0( iridescenceFresnel${lobe}, texture2D( dfgLUT, vec2( material.roughness, dotNVi ) ).rg, material.specularF90 );`;
const METALLIC_F0 = 'material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );';
/** The includes of three's physical fragment shader the film is written into. */
const FILM_INCLUDES = ['#include <iridescence_fragment>', '#include <lights_fragment_begin>'] as const;

/**
 * three's lights_fragment_begin with the film's lobe replaced (its value and its F0), or an error
 * naming what a three.js release no longer has: the dielectric lobe, or over a metal from the base
 * colour (docs/material.md#a-metal-from-its-colour) the metallic one.
 */
function lightsFragmentBegin(metal: boolean): string {
  const begin = ShaderChunk.lights_fragment_begin;
  const [film, f0, lobe] = metal
    ? [METALLIC_FILM, METALLIC_F0, 'Metallic' as const]
    : [DIELECTRIC_FILM, DIELECTRIC_F0, 'Dielectric' as const];
  for (const line of [film, f0])
    if (!begin.includes(line)) throw new Error(`spectralIridescence: three.js's lights_fragment_begin no longer holds ${line}`);
  return begin.replace(film, SPECTRAL_FILM).replace(f0, SPECTRAL_F0(lobe));
}

/** Film tables shared by the materials whose film, light and thickness range are the same. */
const tables = new SharedTextures((key) => new FilmTable((JSON.parse(key) as { quality: FilmQuality }).quality));
/** The context restore each table was last drawn after (contextRestores.ts): a restore empties it. */
const tableRestores = new WeakMap<FilmTable, number>();

/** The material's hooks three calls, as the user set them: ours call them first. */
interface UserHooks {
  onBeforeCompile: Material['onBeforeCompile'];
  customProgramCacheKey: Material['customProgramCacheKey'];
  onBeforeRender: Material['onBeforeRender'];
}

/** What a material upgraded by `spectralIridescence` holds: its options, its uniforms, its table, the user's hooks. */
interface SpectralFilm {
  options: CheckedOptions;
  readonly uniforms: ReturnType<typeof filmColorUniforms>;
  table: FilmTable | null;
  readonly user: UserHooks;
  /** the parameters already warned about (once each) */
  readonly warned: Set<string>;
  /** metalState at the last draw: a change three cannot see (metalness, the base colour) may need a new program */
  drawnMetal: string | null;
}

const films = new WeakMap<MeshPhysicalMaterial, SpectralFilm>();

/** A parameter's value within its domain: as given, or (drawing) clamped to it after a warning. */
type Limit = (name: string, value: number, d: NumberDomain) => number;
const refuse: Limit = (name, value, d) => {
  assertInRange(name, value, d.min, d.max, d.unit);
  return value;
};
const clampWarningOnce =
  (film: SpectralFilm): Limit =>
  (name, value, d) => {
    if (isInDomain(value, d)) return value;
    const clamped = Number.isNaN(value) ? d.min : Math.min(d.max, Math.max(d.min, value));
    if (!film.warned.has(name)) {
      film.warned.add(name);
      console.warn(`spectralIridescence: ${name} ${String(value)} is not allowed; expected ${expectedNumber(d)}; drawn with ${clamped}`);
    }
    return clamped;
  };

/**
 * The film as the demo's settings describe it, from a physical material's glTF parameters: the
 * film (iridescenceIOR) in air over the base (ior), up to the thickness range's larger end.
 * Each is held to the film stack's domain by `limit`, which names three's property.
 */
function filmSettingsOf(m: MeshPhysicalMaterial, o: CheckedOptions, limit: Limit): FilmSettings {
  const d = FILM_STACK_DOMAIN;
  const nFilm = o.film ?? limit('iridescenceIOR', m.iridescenceIOR, d.nFilm);
  const nInside = baseOf(m, o) ?? limit('ior', m.ior, d.nInside);
  const minNm = limit('iridescenceThicknessMinimum', m.iridescenceThicknessMinimum, d.thicknessNm);
  const maxNm = limit('iridescenceThicknessMaximum', m.iridescenceThicknessMaximum, d.thicknessNm);
  return { ...DEFAULT_SETTINGS, ...o, field: 'uniform', thicknessNm: Math.max(minNm, maxNm), nOutside: 1, nFilm, nInside };
}

/**
 * Brings the film's uniforms, light textures and table (built with `renderer` if it changed, or
 * if the renderer's context was restored since) up to the material.
 */
function update(film: SpectralFilm, m: MeshPhysicalMaterial, renderer: WebGLRenderer): void {
  const o = film.options;
  const s = filmSettingsOf(m, o, clampWarningOnce(film));
  if (o.mode === 'table') {
    const table = tables.hold(JSON.stringify({ quality: o.quality, table: tableKey(s) }), film);
    const restores = restoresOf(renderer);
    if (tableRestores.get(table) !== restores) table.invalidate();
    tableRestores.set(table, restores);
    table.update(renderer, s);
    film.table = table;
  } else if (film.table) {
    tables.release(film);
    film.table = null;
  }
  updateFilmColorUniforms(film, s, o.quality, film.table);
}

/** Each material's metal from its colours, and the colours it was made from. */
const metals = new WeakMap<MeshPhysicalMaterial, { readonly key: string; readonly medium: SampledIndex }>();

/**
 * The metal under the film when the material is one and names no base: its index from the base
 * colour (F0) and the edge tint (by default the base colour), per channel (artistMetal.ts).
 */
function metalOf(m: MeshPhysicalMaterial, o: CheckedOptions): SampledIndex | null {
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

/** The GLSL defines of the film (filmColor.glsl's, for the mode). */
// The film is `film` (a medium) or three's iridescenceIOR, a number; the base is `base` (a medium), the metal, or three's ior, a number.
const definesOf = (m: MeshPhysicalMaterial, o: CheckedOptions) =>
  filmColorDefines({ ...o, nFilm: o.film ?? DEFAULT_SETTINGS.nFilm, nInside: baseOf(m, o) ?? DEFAULT_SETTINGS.nInside }, o.quality);

/** What of the program the material's metalness and colour decide: whether the lobe is the metallic one, and over an opaque metal. */
function metalState(m: MeshPhysicalMaterial, o: CheckedOptions): string {
  const metal = metalOf(m, o);
  return metal === null ? '' : absorbsInBand(metal) ? ' metallic' : ' metallic clear';
}

/** The film's part of the program key: the defines, and which lobe is spectral. */
const filmKey = (m: MeshPhysicalMaterial, o: CheckedOptions): string => `${JSON.stringify(definesOf(m, o))}${metalState(m, o)}`;

/** Gives the film new options; a new program only if the defines differ (the old one freed, as setDefines does). */
function setOptions(m: MeshPhysicalMaterial, film: SpectralFilm, options: CheckedOptions): void {
  if (filmKey(m, film.options) !== filmKey(m, options)) {
    m.dispose();
    m.needsUpdate = true;
  }
  film.options = options;
}

/** The user's program key: theirs, or three's default for their onBeforeCompile (its text). */
const userKey = (m: Material, user: UserHooks): string =>
  user.customProgramCacheKey === Material.prototype.customProgramCacheKey
    ? user.onBeforeCompile.toString()
    : user.customProgramCacheKey.call(m);

/**
 * Puts the film in three's hooks, each as an accessor: reading it gives ours, setting it sets the
 * user's, which ours call first (their onBeforeCompile edits three's shader as written, then ours
 * writes the film in; their onBeforeRender runs before the film is brought up to date).
 */
function hook(m: MeshPhysicalMaterial, film: SpectralFilm): void {
  let warnedIncludes = false;
  const ours: UserHooks = {
    onBeforeCompile: (shader: WebGLProgramParametersWithUniforms, renderer: WebGLRenderer) => {
      film.user.onBeforeCompile.call(m, shader, renderer);
      if (!FILM_INCLUDES.every((line) => shader.fragmentShader.includes(line))) {
        if (!warnedIncludes)
          console.warn(`spectralIridescence: onBeforeCompile removed ${FILM_INCLUDES.join(' or ')}; three's film is drawn`);
        warnedIncludes = true;
        return;
      }
      shader.defines = { ...shader.defines, ...definesOf(m, film.options) };
      Object.assign(shader.uniforms, film.uniforms);
      shader.fragmentShader = shader.fragmentShader
        .replace(FILM_INCLUDES[0], `${FILM_INCLUDES[0]}\n#ifdef USE_IRIDESCENCE\n${shaderSource('spectralIridescence.glsl')}\n#endif`)
        .replace(FILM_INCLUDES[1], lightsFragmentBegin(metalOf(m, film.options) !== null));
    },
    // One program per distinct film configuration and user edit (three would otherwise key it by onBeforeCompile's text alone).
    customProgramCacheKey: () => `spectral-iridescence ${filmKey(m, film.options)} ${userKey(m, film.user)}`,
    onBeforeRender: (renderer, scene, camera, geometry, object, group) => {
      film.user.onBeforeRender.call(m, renderer, scene, camera, geometry, object, group);
      // metalness and color are uniforms to three: a metal's coming or going (or its k reaching 0) needs a new program three would not make.
      const state = metalState(m, film.options);
      if (film.drawnMetal !== null && film.drawnMetal !== state) m.needsUpdate = true;
      film.drawnMetal = state;
      if (m.iridescence > 0) update(film, m, renderer);
    },
  };
  for (const name of ['onBeforeCompile', 'customProgramCacheKey', 'onBeforeRender'] as const)
    Object.defineProperty(m, name, {
      configurable: true,
      get: () => ours[name],
      set: (f: UserHooks[typeof name]) => Object.assign(film.user, { [name]: f }),
    });
}

/** The options as properties of a patched MeshPhysicalMaterial, and its clone and copy carrying them (ThinFilmMaterial has its own). */
function addProperties(m: MeshPhysicalMaterial): void {
  const prototype = Object.getPrototypeOf(m) as MeshPhysicalMaterial;
  for (const name of OPTION_NAMES)
    Object.defineProperty(m, name, {
      configurable: true,
      enumerable: true,
      get: () => spectralOption(m, name),
      set: (value: unknown) => setSpectralOption(m, name, value),
    });
  Object.defineProperties(m, {
    clone: { configurable: true, writable: true, value: () => patch(prototype.clone.call(m), films.get(m)!.options) },
    copy: {
      configurable: true,
      writable: true,
      value: (source: Material) => {
        prototype.copy.call(m, source);
        copySpectralFilm(m, source);
        return m;
      },
    },
  });
}

/** Makes `m` spectral with `options` (already checked), or gives it those options if it is. */
function patch<M extends MeshPhysicalMaterial>(m: M, options: CheckedOptions): M & SpectralIridescenceProperties {
  const known = films.get(m);
  if (known) {
    setOptions(m, known, options);
    return m as M & SpectralIridescenceProperties;
  }
  // Kept unbound: each is called on `m`, and three's default program key is onBeforeCompile's own text.
  // eslint-disable-next-line @typescript-eslint/unbound-method
  const user = { onBeforeCompile: m.onBeforeCompile, customProgramCacheKey: m.customProgramCacheKey, onBeforeRender: m.onBeforeRender };
  const film: SpectralFilm = { options, uniforms: filmColorUniforms(), table: null, user, warned: new Set(), drawnMetal: null };
  films.set(m, film);
  hook(m, film);
  if (!(m as { isThinFilmMaterial?: boolean }).isThinFilmMaterial) addProperties(m);
  m.addEventListener('dispose', () => {
    releaseFilmColorTextures(film);
    tables.release(film);
    film.table = null;
  });
  return m as M & SpectralIridescenceProperties;
}

/** An option of a spectral material. */
export const spectralOption = <K extends keyof CheckedOptions>(m: MeshPhysicalMaterial, name: K): CheckedOptions[K] =>
  films.get(m)!.options[name];

/** Sets one option of a spectral material, checked as `spectralIridescence` checks it (a ParameterError names it). */
export function setSpectralOption(m: MeshPhysicalMaterial, name: keyof SpectralIridescenceOptions, value: unknown): void {
  const film = films.get(m)!;
  setOptions(m, film, spectralIridescenceOptions({ ...film.options, [name]: value }));
}

/** Gives `target` the film options of `source` when both are spectral (a material's copy). */
export function copySpectralFilm(target: MeshPhysicalMaterial, source: Material): void {
  const from = films.get(source as MeshPhysicalMaterial);
  const to = films.get(target);
  if (from && to) setOptions(target, to, from.options);
}

/**
 * Makes a MeshPhysicalMaterial's iridescence spectral: wherever three.js would evaluate its
 * thin film over the dielectric base (`evalIridescence` in lights_fragment_begin: Schlick
 * Fresnel, two orders of the Airy sum, a Gaussian fit of the colour-matching functions, no
 * illuminant), the material computes the film's reflectance as the demo does (every order,
 * Fresnel per polarisation, the CIE observer under the chosen light; see docs/material.md).
 * Everything else of the physical material is three's own. The glTF parameters are read where
 * three keeps them; the base's index is `ior`. The options and the film's parameters are checked
 * here (a ParameterError names the first bad one); a parameter set out of range later is clamped
 * when drawn, with a warning. The options become properties of the material (`material.mode =
 * 'fourier'`); the user's `onBeforeCompile`, `customProgramCacheKey` and `onBeforeRender` are
 * called before the film's; `clone()` and `copy()` carry the options. Calling it again changes
 * the options; materials with equal options share one program, and materials with equal films
 * share one table and the light's textures, freed when the last holder's material is disposed.
 */
export function spectralIridescence<M extends MeshPhysicalMaterial>(
  material: M,
  options: SpectralIridescenceOptions = {},
): M & SpectralIridescenceProperties {
  const checked = spectralIridescenceOptions(options);
  filmSettingsOf(material, checked, refuse);
  return patch(material, checked);
}

/** Whether `material` has been upgraded by `spectralIridescence` (a ThinFilmMaterial always is). */
export const isSpectralIridescence = (material: Material): material is MeshPhysicalMaterial & SpectralIridescenceProperties =>
  films.has(material as MeshPhysicalMaterial);

/**
 * Upgrades every MeshPhysicalMaterial with iridescence under `root` (a glTF's scene, say) to the
 * spectral film (`spectralIridescence`, with the same options); returns the materials upgraded.
 */
export function useSpectralIridescence(root: Object3D, options: SpectralIridescenceOptions = {}): MeshPhysicalMaterial[] {
  const found = new Set<MeshPhysicalMaterial>();
  root.traverse((o) => {
    const m = (o as { material?: unknown }).material;
    for (const material of Array.isArray(m) ? m : [m]) {
      const p = material as MeshPhysicalMaterial | undefined;
      if (p?.isMeshPhysicalMaterial && p.iridescence > 0) found.add(p);
    }
  });
  for (const m of found) spectralIridescence(m, options);
  return [...found];
}

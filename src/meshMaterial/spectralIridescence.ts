import { type Material, type MeshPhysicalMaterial, type Object3D, type WebGLRenderer } from 'three';
import { filmColorUniforms, releaseFilmColorTextures, updateFilmColorUniforms } from '../film/filmColor.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { FilmTable, tableKey } from '../film/filmTable.ts';
import { uniformField } from '../fields/uniformField.ts';
import { methodReads } from '../methods/methods.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import {
  type CheckedOptions,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from './spectralIridescenceOptions.ts';
import { restoresOf } from './contextRestores.ts';
import { chainHooks } from './materialHooks.ts';
import { clampWithWarning, filmDefinesOf, filmKeyOf, filmSettingsOf, metalOf, metalStateOf, refuse } from './materialFilm.ts';
import { NODE_RENDERER_MESSAGE, warnWhereDrawnAsNodes } from './nodeRendererWarning.ts';
import { spectralFragmentShader } from './spectralFragmentShader.ts';
import { type SpectralFilm, addFilm, copySpectralFilm, defineOptionProperties, filmOf, setOptions, warnOnce } from './spectralFilm.ts';
import { spectralMaterialJson } from './spectralIridescenceJson.ts';

/** Film tables shared by the materials whose film, light and thickness range are the same. */
const tables = new SharedTextures((key) => new FilmTable((JSON.parse(key) as { quality: FilmQuality }).quality));
/** The context restore each table was last drawn after (contextRestores.ts): a restore empties it. */
const tableRestores = new WeakMap<FilmTable, number>();

/**
 * Brings the film's uniforms, light textures and table (built with `renderer` if it changed, or
 * if the renderer's context was restored since) up to the material. Called inside three's render:
 * a parameter out of its domain is drawn clamped, with a warning, never thrown.
 */
function update(film: SpectralFilm, m: MeshPhysicalMaterial, renderer: WebGLRenderer): void {
  const o = film.options;
  const s = filmSettingsOf(
    m,
    o,
    clampWithWarning((name, message) => warnOnce(film, name, message)),
  );
  if (s.mode !== o.mode) warnOnce(film, 'layers', `mode ${o.mode} has no closed form for a stack of films: drawn with mode ${s.mode}`);
  if (methodReads(s.mode, 'table')) {
    // The film is the same over the surface and does not change with time: three's thickness (its map scales it).
    const maxThicknessNm = uniformField.maxThicknessNm({ thicknessNm: s.thicknessNm, timeSeconds: 0 }, null);
    const table = tables.hold(JSON.stringify({ quality: o.quality, table: tableKey(s, maxThicknessNm) }), film);
    const restores = restoresOf(renderer);
    if (tableRestores.get(table) !== restores) table.invalidate();
    tableRestores.set(table, restores);
    table.update(renderer, s, maxThicknessNm);
    film.table = table;
  } else if (film.table) {
    tables.release(film);
    film.table = null;
  }
  updateFilmColorUniforms(film, s, o.quality, film.table);
}

/**
 * The film in three's hooks (materialHooks.ts), after the user's: onBeforeCompile writes it into
 * three's shader, or where it cannot (a user's edit or a three.js release took a line it needs)
 * leaves three's film, with a warning, rather than throw inside render; the program key holds the
 * film's defines and the user's key; onBeforeRender brings the film up to date.
 */
function hook(m: MeshPhysicalMaterial, film: SpectralFilm): void {
  chainHooks(m, {
    onBeforeCompile: (shader) => {
      const fragment = spectralFragmentShader(shader.fragmentShader, metalOf(m, film.options) !== null);
      if (typeof fragment !== 'string') return warnOnce(film, fragment.missing, `no ${fragment.missing}; three's film is drawn`);
      shader.defines = { ...shader.defines, ...filmDefinesOf(m, film.options) };
      Object.assign(shader.uniforms, film.uniforms);
      shader.fragmentShader = fragment;
    },
    // One program per distinct film configuration and user edit (three would otherwise key it by onBeforeCompile's text alone).
    customProgramCacheKey: (userKey) => `spectral-iridescence ${filmKeyOf(m, film.options)} ${userKey}`,
    onBeforeRender: (renderer) => {
      // metalness and color are uniforms to three: a metal's coming or going (or its k reaching 0) needs a new program three would not make.
      const state = metalStateOf(m, film.options);
      if (film.drawnMetal !== null && film.drawnMetal !== state) m.needsUpdate = true;
      film.drawnMetal = state;
      if (m.iridescence > 0) update(film, m, renderer);
    },
  });
}

/**
 * An upgraded MeshPhysicalMaterial's options as properties, and its clone, copy and JSON carrying
 * them (a ThinFilmMaterial has these on its class).
 */
function addMaterialMethods(m: MeshPhysicalMaterial): void {
  defineOptionProperties(m);
  const prototype = Object.getPrototypeOf(m) as MeshPhysicalMaterial;
  const method = (value: unknown) => ({ configurable: true, writable: true, value });
  Object.defineProperties(m, {
    clone: method(() => patch(prototype.clone.call(m), filmOf(m)!.options)),
    copy: method((source: Material) => {
      prototype.copy.call(m, source);
      copySpectralFilm(m, source);
      return m;
    }),
    toJSON: method((meta?: Parameters<Material['toJSON']>[0]) => spectralMaterialJson(prototype.toJSON.call(m, meta), filmOf(m)!.options)),
  });
}

/** Makes `m` spectral with `options` (already checked), or gives it those options if it is. */
function patch<M extends MeshPhysicalMaterial>(m: M, options: CheckedOptions): M & SpectralIridescenceProperties {
  const known = filmOf(m);
  if (known) {
    setOptions(m, known, options);
    return m as M & SpectralIridescenceProperties;
  }
  const uniforms = { ...filmColorUniforms(), ...filmStackUniforms() };
  const film: SpectralFilm = { options, uniforms, table: null, warned: new Set(), drawnMetal: null };
  addFilm(m, film);
  hook(m, film);
  warnWhereDrawnAsNodes(m, () => warnOnce(film, 'node renderer', NODE_RENDERER_MESSAGE));
  if (!(m as { isThinFilmMaterial?: boolean }).isThinFilmMaterial) addMaterialMethods(m);
  m.addEventListener('dispose', () => {
    releaseFilmColorTextures(film);
    tables.release(film);
    film.table = null;
  });
  return m as M & SpectralIridescenceProperties;
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
 * called before the film's; `clone()`, `copy()` and `toJSON()` carry the options. Calling it
 * again changes the options; materials with equal options share one program, and materials with
 * equal films share one table and the light's textures, freed when the last holder's material is
 * disposed.
 */
export function spectralIridescence<M extends MeshPhysicalMaterial>(
  material: M,
  options: SpectralIridescenceOptions = {},
): M & SpectralIridescenceProperties {
  const checked = spectralIridescenceOptions(options);
  filmSettingsOf(material, checked, refuse);
  return patch(material, checked);
}

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

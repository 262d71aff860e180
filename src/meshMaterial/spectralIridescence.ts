import { type Material, type MeshPhysicalMaterial, type Object3D } from 'three';
import { ParameterError } from '../input/validate.ts';
import {
  type CheckedOptions,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from './spectralIridescenceOptions.ts';
import { chainHooks } from './materialHooks.ts';
import { filmParametersOf, refuse } from './materialParameters.ts';
import { NODE_RENDERER_MESSAGE, warnWhereDrawnAsNodes } from './nodeRendererWarning.ts';
import { loadDrawing, loadedDrawing } from './spectralDrawing.ts';
import {
  type SpectralFilm,
  addFilm,
  copySpectralFilm,
  defineOptionProperties,
  filmOf,
  newFilm,
  setOptions,
  warnOnce,
} from './spectralFilm.ts';
import { spectralMaterialJson } from './spectralIridescenceJson.ts';
import { materialsUnder } from './materialsUnder.ts';

/**
 * The film in three's hooks (materialHooks.ts), after the user's, each the drawing's
 * (materialDrawing.ts) once it is loaded: onBeforeCompile writes the film into three's shader, the
 * program key holds the film's defines and the user's key, onBeforeRender brings the film up to
 * date. Until the drawing is loaded (whenSpectralReady), the material draws three's own film, in a
 * program keyed apart; the drawing's arrival moves the material's version, so the next draw compiles the film.
 */
function hook(m: MeshPhysicalMaterial, film: SpectralFilm): void {
  chainHooks(m, {
    onBeforeCompile: (shader) => loadedDrawing()?.compileFilm(m, film, shader),
    // One program per distinct film configuration and user edit (three would otherwise key it by onBeforeCompile's text alone).
    customProgramCacheKey: (userKey) => `spectral-iridescence ${loadedDrawing()?.filmKeyOf(m, film.options) ?? 'loading'} ${userKey}`,
    onBeforeRender: (renderer, scene) => loadedDrawing()?.drawFilm(m, film, renderer, scene),
  });
  const loaded = loadedDrawing();
  if (loaded) film.programKey = loaded.filmKeyOf;
  else
    void loadDrawing().then((drawing) => {
      film.programKey = drawing.filmKeyOf;
      m.needsUpdate = true;
      void drawing.prepareFilm(m, film);
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
  const film = newFilm(options);
  addFilm(m, film);
  hook(m, film);
  warnWhereDrawnAsNodes(m, () => warnOnce(film, 'node renderer', NODE_RENDERER_MESSAGE));
  if (!(m as { isThinFilmMaterial?: boolean }).isThinFilmMaterial) addMaterialMethods(m);
  m.addEventListener('dispose', () => loadedDrawing()?.releaseFilm(film));
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
  filmParametersOf(material, checked, refuse);
  return patch(material, checked);
}

/**
 * Upgrades every MeshPhysicalMaterial with iridescence under `root` (a glTF's scene, say) to the
 * spectral film (`spectralIridescence`, with the same options); returns the materials upgraded.
 */
export function useSpectralIridescence(root: Object3D, options: SpectralIridescenceOptions = {}): MeshPhysicalMaterial[] {
  const found = materialsUnder(root, hasIridescence);
  for (const m of found) spectralIridescence(m, options);
  return found;
}

const hasIridescence = (m: unknown): m is MeshPhysicalMaterial => {
  const p = m as MeshPhysicalMaterial | undefined;
  return p?.isMeshPhysicalMaterial === true && p.iridescence > 0;
};

/**
 * A promise kept once everything `material`'s film needs is loaded and computed: the film's
 * drawing and the data it computes from (a chunk of its own, fetched the first time a material is
 * made spectral), and what its table and the light's textures are computed from (the light's
 * spectral transform, a dispersive film's row terms, in Web Workers). The next draw builds the
 * table on the GPU before drawing the film: the next frame shows the settled film, so a screenshot
 * waits for this promise, then draws. A ParameterError for a material that is not spectral.
 */
export async function whenSpectralReady(material: Material): Promise<void> {
  const film = filmOf(material);
  if (!film)
    throw new ParameterError('material', 'whenSpectralReady: the material is not spectral; expected one spectralIridescence upgraded');
  const drawing = await loadDrawing();
  await drawing.prepareFilm(material as MeshPhysicalMaterial, film);
}

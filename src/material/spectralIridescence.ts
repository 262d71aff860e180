import {
  MeshPhysicalMaterial,
  type MeshPhysicalMaterialParameters,
  type Object3D,
  ShaderChunk,
  type WebGLProgramParametersWithUniforms,
  type WebGLRenderer,
} from 'three';
import { FILM_STACK_DOMAIN, POLARIZATIONS, type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec, illuminantFromJson } from '../physics/illuminants.ts';
import { NORMALIZATIONS, type Normalization } from '../physics/spectralWeights.ts';
import { assertInRange, oneOf } from '../physics/validate.ts';
import { filmColorDefines, filmColorUniforms, releaseFilmColorTextures, updateFilmColorUniforms } from '../film/filmColor.ts';
import { DEFAULT_SETTINGS } from '../settings/filmParameters.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../settings/filmQuality.ts';
import { type FilmSettings, MODES } from '../settings/filmSettings.ts';
import { FilmTable, tableKey } from '../film/filmTable.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';

/** How the film is computed and seen: the demo's `mode`, `illuminant`, `polarization`, `normalization`. */
export interface SpectralIridescenceOptions {
  /** `table` (default: one lookup in a table the GPU builds), `fourier` (the Airy series per fragment) or `exact` (binned integral) */
  readonly mode?: (typeof MODES)[number];
  readonly illuminant?: IlluminantSpec;
  readonly polarization?: Polarization;
  readonly normalization?: Normalization;
  /** the table's layout and bins (the demo's defaults) */
  readonly quality?: FilmQuality;
}

type Options = Required<SpectralIridescenceOptions>;

/** The options with their defaults, each checked (a ParameterError names the first bad one). */
export function spectralIridescenceOptions(o: SpectralIridescenceOptions = {}): Options {
  return {
    mode: oneOf('mode', o.mode ?? 'table', MODES),
    illuminant: illuminantFromJson(o.illuminant ?? DEFAULT_SETTINGS.illuminant),
    polarization: oneOf('polarization', o.polarization ?? DEFAULT_SETTINGS.polarization, POLARIZATIONS),
    normalization: oneOf('normalization', o.normalization ?? DEFAULT_SETTINGS.normalization, NORMALIZATIONS),
    quality: o.quality ?? DEFAULT_FILM_QUALITY,
  };
}

/** The call in three's lights_fragment_begin chunk that gives the film over the dielectric base. */
const DIELECTRIC_FILM = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor )';
const SPECTRAL_FILM = 'tfcSpectralIridescence( material.iridescenceThickness, dotNVi )';
/**
 * three's F0 for the film's image-based light: Schlick's curve inverted at n·v. Ours inverts the
 * DFG table the light is then integrated with (docs/material.md#the-films-f0-for-image-based-light),
 * so a mirror-smooth surface reflects the film's own value at n·v at every angle.
 */
const DIELECTRIC_F0 = 'material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );';
const SPECTRAL_F0 =
  'material.iridescenceF0Dielectric = tfcSpectralIridescenceF0( iridescenceFresnelDielectric, texture2D( dfgLUT, vec2( material.roughness, dotNVi ) ).rg, material.specularF90 );';

/** three's lights_fragment_begin with the two replacements, or an error naming what a three.js release no longer has. */
function lightsFragmentBegin(): string {
  const begin = ShaderChunk.lights_fragment_begin;
  for (const line of [DIELECTRIC_FILM, DIELECTRIC_F0])
    if (!begin.includes(line)) throw new Error(`spectralIridescence: three.js's lights_fragment_begin no longer holds ${line}`);
  return begin.replace(DIELECTRIC_FILM, SPECTRAL_FILM).replace(DIELECTRIC_F0, SPECTRAL_F0);
}

/** Film tables shared by the materials whose film, light and thickness range are the same. */
const tables = new SharedTextures((key) => new FilmTable((JSON.parse(key) as { quality: FilmQuality }).quality));

/**
 * The film as the demo's settings describe it, from a physical material's glTF parameters: the
 * film (iridescenceIOR) in air over the base (ior), up to the thickness range's larger end.
 * Each index is checked against the film stack's domain; a ParameterError names three's property.
 */
function filmSettingsOf(m: MeshPhysicalMaterial, o: Options): FilmSettings {
  const { iridescenceThicknessMinimum: minNm, iridescenceThicknessMaximum: maxNm } = m;
  assertInRange('iridescenceIOR', m.iridescenceIOR, FILM_STACK_DOMAIN.nFilm.min, FILM_STACK_DOMAIN.nFilm.max);
  assertInRange('ior', m.ior, FILM_STACK_DOMAIN.nInside.min, FILM_STACK_DOMAIN.nInside.max);
  const { min, max, unit } = FILM_STACK_DOMAIN.thicknessNm;
  assertInRange('iridescenceThicknessMinimum', minNm, min, max, unit);
  assertInRange('iridescenceThicknessMaximum', maxNm, min, max, unit);
  return {
    ...DEFAULT_SETTINGS,
    ...o,
    field: 'uniform',
    thicknessNm: Math.max(minNm, maxNm),
    nOutside: 1,
    nFilm: m.iridescenceIOR,
    nInside: m.ior,
  };
}

/** What a material upgraded by `spectralIridescence` holds: its options, its uniforms, its table. */
interface SpectralFilm {
  options: Options;
  readonly uniforms: ReturnType<typeof filmColorUniforms>;
  table: FilmTable | null;
}

const films = new WeakMap<MeshPhysicalMaterial, SpectralFilm>();

/** Brings the film's uniforms, light textures and table (built with `renderer` if it changed) up to the material. */
function update(film: SpectralFilm, m: MeshPhysicalMaterial, renderer: WebGLRenderer): void {
  const o = film.options;
  const s = filmSettingsOf(m, o);
  if (o.mode === 'table') {
    const table = tables.hold(JSON.stringify({ quality: o.quality, table: tableKey(s) }), film);
    table.update(renderer, s);
    film.table = table;
  } else if (film.table) {
    tables.release(film);
    film.table = null;
  }
  updateFilmColorUniforms(film, s, o.quality, film.table);
}

/** The GLSL defines of the film (filmColor.glsl's, for the mode). */
// The material's film index is three's iridescenceIOR, one number: a constant film's defines.
const definesOf = (o: Options) => filmColorDefines({ ...o, nFilm: DEFAULT_SETTINGS.nFilm }, o.quality);

/**
 * Makes a MeshPhysicalMaterial's iridescence spectral: wherever three.js would evaluate its
 * thin film over the dielectric base (`evalIridescence` in lights_fragment_begin: Schlick
 * Fresnel, two orders of the Airy sum, a Gaussian fit of the colour-matching functions, no
 * illuminant), the material computes the film's reflectance as the demo does (every order,
 * Fresnel per polarisation, the CIE observer under the chosen light; see docs/material.md).
 * Everything else of the physical material is three's own: base colour, metalness, roughness,
 * maps, transmission, lights, environment, shadows, tone mapping. The glTF parameters are read
 * where three keeps them: `iridescence`, `iridescenceIOR`, `iridescenceThicknessMinimum`, `iridescenceThicknessMaximum`,
 * `iridescenceMap`, `iridescenceThicknessMap`; the base's index is `ior`. The metallic lobe (a
 * metal's F0 under the film) stays three's. Calling it again changes the options; materials with
 * equal options share one program, and materials with equal films share one table and the
 * light's textures, freed when the last holder's material is disposed.
 */
export function spectralIridescence<M extends MeshPhysicalMaterial>(material: M, options: SpectralIridescenceOptions = {}): M {
  const checked = spectralIridescenceOptions(options);
  filmSettingsOf(material, checked);
  const known = films.get(material);
  if (known) {
    if (JSON.stringify(definesOf(known.options)) !== JSON.stringify(definesOf(checked))) {
      material.dispose(); // frees the old program (and, below, the old textures), as setDefines does
      material.needsUpdate = true;
    }
    known.options = checked;
    return material;
  }
  const film: SpectralFilm = {
    options: checked,
    uniforms: filmColorUniforms(),
    table: null,
  };
  films.set(material, film);
  material.onBeforeCompile = (shader: WebGLProgramParametersWithUniforms) => {
    shader.defines = { ...shader.defines, ...definesOf(film.options) };
    Object.assign(shader.uniforms, film.uniforms);
    shader.fragmentShader = shader.fragmentShader
      .replace(
        '#include <iridescence_fragment>',
        `#include <iridescence_fragment>\n#ifdef USE_IRIDESCENCE\n${shaderSource('spectralIridescence.glsl')}\n#endif`,
      )
      .replace('#include <lights_fragment_begin>', lightsFragmentBegin());
  };
  // One program per distinct film configuration (three would otherwise key it by onBeforeCompile's text alone).
  material.customProgramCacheKey = () => `spectral-iridescence ${JSON.stringify(definesOf(film.options))}`;
  material.onBeforeRender = (renderer) => {
    if (material.iridescence > 0) update(film, material, renderer);
  };
  material.addEventListener('dispose', () => {
    releaseFilmColorTextures(film);
    tables.release(film);
    film.table = null;
  });
  return material;
}

/** Whether `material` has been upgraded by `spectralIridescence`. */
export const isSpectralIridescence = (material: MeshPhysicalMaterial): boolean => films.has(material);

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

/**
 * A MeshPhysicalMaterial whose iridescence is the spectral film from the start (iridescence 1
 * unless `parameters` say otherwise): `new ThinFilmMaterial({ iridescenceIOR: 1.33,
 * iridescenceThicknessMinimum: 0, iridescenceThicknessMaximum: 450 }, { illuminant: 'D65' })`.
 */
export class ThinFilmMaterial extends MeshPhysicalMaterial {
  constructor(parameters: MeshPhysicalMaterialParameters = {}, film: SpectralIridescenceOptions = {}) {
    super({ iridescence: 1, ...parameters });
    spectralIridescence(this, film);
  }
}

/**
 * The spectral film for three.js's WebGPURenderer (`thin-film-color/webgpu`): a
 * MeshPhysicalNodeMaterial, or a classic MeshPhysicalMaterial that WebGPURenderer draws through
 * its node copy, with the film's lighting model (spectralLightingModel.ts) in place of three's.
 */
import { type Material, type MeshPhysicalMaterial, type Object3D } from 'three';
import { clamp, ior, iridescenceIOR, vec2 } from 'three/tsl';
import { MeshPhysicalNodeMaterial, type NodeBuilder, type PhysicalLightingModel } from 'three/webgpu';
import { filmColorUniforms, releaseFilmColorTextures, updateFilmColorUniforms } from '../film/filmColor.ts';
import { filmSpectralBins } from '../film/filmFillGpu.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { spectralBinDefines } from '../film/spectralBinsTexture.ts';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { LAYERS_DOMAIN } from '../physics/stackFilms.ts';
import { filmFill } from '../methods/filmFills.ts';
import { clampWithWarning, filmKeyOf, filmSettingsOf, metalOf, metalStateOf, refuse } from '../meshMaterial/materialFilm.ts';
import { type SpectralFilm, addFilm, defineOptionProperties, filmOf, setOptions, warnOnce } from '../meshMaterial/spectralFilm.ts';
import {
  type CheckedOptions,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from '../meshMaterial/spectralIridescenceOptions.ts';
import { type FloatNode } from './complex.ts';
import { type FilmInputs, filmInputs, setFilmInputs } from './filmInputs.ts';
import { CHANNEL_KINDS } from './filmReflectance.ts';
import { type FilmNodes, filmXyz, xyzToLinearWorking } from './filmColor.ts';
import { FilmUpdateNode } from './filmUpdateNode.ts';
import { SpectralLightingModel } from './spectralLightingModel.ts';

/** A material the entry makes spectral: a node material, or a classic one WebGPURenderer draws through its node copy. */
export type PhysicalMaterial = MeshPhysicalNodeMaterial | MeshPhysicalMaterial;

/** A physical material as the shared film code reads it (the glTF parameters both kinds hold). */
const physical = (m: PhysicalMaterial) => m as MeshPhysicalMaterial;

const inputsOf = new WeakMap<Material, FilmInputs>();

/** Brings the film's uniforms and the node inputs up to the material; clamps (with a warning) what is out of its domain. */
function update(film: SpectralFilm, m: PhysicalMaterial, inputs: FilmInputs): void {
  const o = film.options;
  const s = filmSettingsOf(
    physical(m),
    o,
    clampWithWarning((name, message) => warnOnce(film, name, message)),
  );
  if (s.mode !== o.mode) warnOnce(film, 'layers', `mode ${o.mode} has no closed form for a stack of films: drawn with mode ${s.mode}`);
  const state = metalStateOf(physical(m), o);
  if (film.drawnMetal !== null && film.drawnMetal !== state) m.needsUpdate = true;
  film.drawnMetal = state;
  updateFilmColorUniforms(film, { ...s, mode: 'exact' }, o.quality, null);
  setFilmInputs(inputs, film.uniforms);
}

/** The film's nodes for the material's options: its fill and channels, its bins, its media (three's iridescenceIOR and ior unless named). */
function filmNodes(m: PhysicalMaterial, o: CheckedOptions, inputs: FilmInputs): FilmNodes {
  const s = filmSettingsOf(
    physical(m),
    o,
    clampWithWarning(() => {}),
  );
  const q = o.quality;
  const bins = spectralBinDefines(filmSpectralBins(s, q, q.exactSpectralBins), q.spectralTailTolerance);
  const d = FILM_STACK_DOMAIN;
  const three = (n: FloatNode, domain: { min: number; max: number }) => vec2(clamp(n, domain.min, domain.max), 0);
  return {
    fill: filmFill(s),
    kinds: CHANNEL_KINDS[o.polarization],
    bins: { count: bins.TFC_SPECTRAL_BINS!, first: bins.TFC_SPECTRAL_BIN_FIRST!, end: bins.TFC_SPECTRAL_BIN_END!, weights: inputs.weights },
    nFilm: o.film === null ? three(iridescenceIOR, d.nFilm) : inputs.nFilm,
    nInside: o.base === null && metalOf(physical(m), o) === null ? three(ior, d.nInside) : inputs.nInside,
    knots: inputs.knots,
    stack: { layers: inputs.layers, count: inputs.layerCount, maxCount: LAYERS_DOMAIN.count.max },
  };
}

/**
 * three's lighting model for the material, or where it draws iridescence the film's: `this` is
 * the node material built (a classic material's node copy), `builder.material` the material made
 * spectral.
 */
function setupLightingModel(this: MeshPhysicalNodeMaterial, builder: NodeBuilder): PhysicalLightingModel {
  const three: PhysicalLightingModel = MeshPhysicalNodeMaterial.prototype.setupLightingModel.call(this);
  const m = builder.material as PhysicalMaterial;
  const film = filmOf(m);
  const inputs = inputsOf.get(m);
  if (!film || !inputs || !three.iridescence) return three;
  const nodes = filmNodes(m, film.options, inputs);
  const filmRgb = (thicknessNm: FloatNode, cosIncidence: FloatNode) =>
    new FilmUpdateNode(xyzToLinearWorking(filmXyz(nodes, thicknessNm, cosIncidence)), () => update(film, m, inputs)) as never;
  return new SpectralLightingModel(three, filmRgb, metalOf(physical(m), film.options) !== null);
}

/** The film's hooks on `m`: its lighting model (enumerable, so a classic material's node copy takes it), its part of the program key. */
function hook(m: PhysicalMaterial): void {
  // eslint-disable-next-line @typescript-eslint/unbound-method -- called on `m` below
  const userKey = m.customProgramCacheKey;
  Object.defineProperties(m, {
    setupLightingModel: { configurable: true, enumerable: true, writable: true, value: setupLightingModel },
    customProgramCacheKey: {
      configurable: true,
      writable: true,
      value: () => `${userKey.call(m)} spectral-iridescence ${filmKeyOf(physical(m), filmOf(m)!.options)}`,
    },
  });
}

/** Makes `m` spectral with `options` (already checked), or gives it those options if it is. */
function patch<M extends PhysicalMaterial>(m: M, options: CheckedOptions): M & SpectralIridescenceProperties {
  const known = filmOf(m);
  if (known) {
    setOptions(physical(m), known, options);
    return m as M & SpectralIridescenceProperties;
  }
  const film: SpectralFilm = {
    options,
    uniforms: { ...filmColorUniforms(), ...filmStackUniforms() },
    table: null,
    warned: new Set(),
    drawnMetal: null,
  };
  const inputs = filmInputs();
  addFilm(physical(m), film);
  inputsOf.set(m, inputs);
  hook(m);
  defineOptionProperties(m);
  update(film, m, inputs);
  m.needsUpdate = true;
  m.addEventListener('dispose', () => releaseFilmColorTextures(film));
  return m as M & SpectralIridescenceProperties;
}

/**
 * Makes a physical material's iridescence spectral for WebGPURenderer (docs/material.md): a
 * MeshPhysicalNodeMaterial, or a classic MeshPhysicalMaterial (a glTF loader's). Its options are
 * the WebGL entry's, checked as there (a ParameterError names the first bad one); three's nodes
 * (iridescenceNode, iridescenceIORNode, iridescenceThicknessNode) keep driving the film, their
 * values clamped to the film's domain on the GPU.
 */
export function spectralIridescence<M extends PhysicalMaterial>(
  material: M,
  options: SpectralIridescenceOptions = {},
): M & SpectralIridescenceProperties {
  const checked = spectralIridescenceOptions(options);
  filmSettingsOf(physical(material), checked, refuse);
  return patch(material, checked);
}

const hasIridescence = (m: unknown): m is PhysicalMaterial => {
  const p = m as Partial<MeshPhysicalNodeMaterial & MeshPhysicalMaterial> | undefined;
  return (
    (p?.isMeshPhysicalMaterial === true || p?.isMeshPhysicalNodeMaterial === true) && ((p.iridescence ?? 0) > 0 || !!p.iridescenceNode)
  );
};

/** Upgrades every physical material with iridescence under `root` (a glTF's scene, say); returns the materials upgraded. */
export function useSpectralIridescence(root: Object3D, options: SpectralIridescenceOptions = {}): PhysicalMaterial[] {
  const found = new Set<PhysicalMaterial>();
  root.traverse((o) => {
    const m = (o as { material?: unknown }).material;
    for (const material of Array.isArray(m) ? m : [m]) if (hasIridescence(material)) found.add(material);
  });
  for (const m of found) spectralIridescence(m, options);
  return [...found];
}

/** A promise that resolves once every table and datum the material's film needs is built (so a screenshot can wait for it). */
export const whenSpectralReady = (material: Material): Promise<void> =>
  filmOf(material) ? Promise.resolve() : Promise.reject(new Error('whenSpectralReady: the material is not spectral (spectralIridescence)'));

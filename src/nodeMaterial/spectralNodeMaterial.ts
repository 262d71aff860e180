/**
 * The spectral film for three.js's WebGPURenderer (`thin-film-color/webgpu`): a
 * MeshPhysicalNodeMaterial, or a classic MeshPhysicalMaterial that WebGPURenderer draws through
 * its node copy, with the film's lighting model (nodeFilm.ts) in place of three's.
 */
import { type Material, type MeshPhysicalMaterial, type Object3D } from 'three';
import { type MeshPhysicalNodeMaterial } from 'three/webgpu';
import { filmColorUniforms, releaseFilmColorTextures } from '../film/filmColor.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { filmKeyOf, filmSettingsOf } from '../meshMaterial/materialFilm.ts';
import { refuse } from '../meshMaterial/materialParameters.ts';
import { materialsUnder } from '../meshMaterial/materialsUnder.ts';
import { type SpectralFilm, addFilm, defineOptionProperties, filmOf, setOptions } from '../meshMaterial/spectralFilm.ts';
import {
  type CheckedOptions,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from '../meshMaterial/spectralIridescenceOptions.ts';
import { filmInputs } from './filmInputs.ts';
import {
  type NodeFilm,
  type PhysicalMaterial,
  addNodeFilm,
  drawsTable,
  nodeFilmOf,
  physical,
  setupLightingModel,
  updateNodeFilm,
} from './nodeFilm.ts';

export type { PhysicalMaterial } from './nodeFilm.ts';

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
    programKey: filmKeyOf,
  };
  const f: NodeFilm = { film, inputs: filmInputs(), table: null };
  addFilm(physical(m), film);
  addNodeFilm(m, f);
  hook(m);
  defineOptionProperties(m);
  updateNodeFilm(f, m, null);
  m.needsUpdate = true;
  m.addEventListener('dispose', () => {
    releaseFilmColorTextures(film);
    f.table?.dispose();
    f.table = null;
  });
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
  const found = materialsUnder(root, hasIridescence);
  for (const m of found) spectralIridescence(m, options);
  return found;
}

/** How often whenSpectralReady looks whether the material's table is drawn. */
const READY_POLL_MS = 16;

/**
 * A promise that resolves once every table and datum the material's film needs is built (its
 * table is drawn by the first render that draws the material), so a screenshot can wait for it.
 */
export function whenSpectralReady(material: Material): Promise<void> {
  const m = material as PhysicalMaterial;
  const f = nodeFilmOf(m);
  if (!f)
    return Promise.reject(new Error('whenSpectralReady: the material is not spectral (spectralIridescence of thin-film-color/webgpu)'));
  const ready = () => {
    const s = filmSettingsOf(physical(m), f.film.options, (_, value) => value);
    return !drawsTable(m, s) || f.table?.holds(s) === true;
  };
  return new Promise((resolve) => {
    const poll = () => (ready() ? resolve() : setTimeout(poll, READY_POLL_MS));
    poll();
  });
}

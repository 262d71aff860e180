/**
 * The spectral film for three.js's WebGPURenderer (`thin-film-color/webgpu`): a
 * MeshPhysicalNodeMaterial, or a classic MeshPhysicalMaterial that WebGPURenderer draws through
 * its node copy, with the film's lighting model (nodeFilm.ts) in place of three's.
 */
import { type Material, type MeshPhysicalMaterial, type Object3D } from 'three';
import { MeshPhysicalNodeMaterial, type NodeBuilder, type PhysicalLightingModel } from 'three/webgpu';
import { ParameterError } from '../input/validate.ts';
import { filmParametersOf, refuse } from '../meshMaterial/materialParameters.ts';
import { materialsUnder } from '../meshMaterial/materialsUnder.ts';
import { type SpectralFilm, addFilm, defineOptionProperties, filmOf, newFilm, setOptions } from '../meshMaterial/spectralFilm.ts';
import {
  type CheckedOptions,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from '../meshMaterial/spectralIridescenceOptions.ts';
import { type PhysicalMaterial, physical } from './physicalMaterial.ts';
import { nodeDrawing } from './spectralNodeDrawing.ts';

export type { PhysicalMaterial } from './physicalMaterial.ts';

/** three's lighting model until the film's drawing is loaded, then the drawing's (nodeFilm.ts). */
function setupLightingModel(this: MeshPhysicalNodeMaterial, builder: NodeBuilder): PhysicalLightingModel {
  const drawing = nodeDrawing.loaded();
  return drawing ? drawing.setupLightingModel.call(this, builder) : MeshPhysicalNodeMaterial.prototype.setupLightingModel.call(this);
}

/**
 * The film's hooks on `m`: its lighting model (enumerable, so a classic material's node copy
 * takes it) and its part of the program key ('loading' until the drawing is here, whose arrival
 * moves the material's version). The key names the material: three shares one program among
 * materials of equal keys, and with it the nodes built for the first of them, whose film's
 * uniforms and table are that material's alone.
 */
function hook(m: PhysicalMaterial, film: SpectralFilm): void {
  // eslint-disable-next-line @typescript-eslint/unbound-method -- called on `m` below
  const userKey = m.customProgramCacheKey;
  Object.defineProperties(m, {
    setupLightingModel: { configurable: true, enumerable: true, writable: true, value: setupLightingModel },
    customProgramCacheKey: {
      configurable: true,
      writable: true,
      value: () => `${userKey.call(m)} spectral-iridescence ${m.uuid} ${nodeDrawing.loaded()?.nodeFilmKey(m, film) ?? 'loading'}`,
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
  const film = newFilm(options);
  addFilm(physical(m), film);
  hook(m, film);
  defineOptionProperties(m);
  let disposed = false;
  m.addEventListener('dispose', () => {
    disposed = true;
    nodeDrawing.loaded()?.releaseNodeFilm(m);
  });
  const loaded = nodeDrawing.loaded();
  if (loaded) loaded.startNodeFilm(m, film);
  else void nodeDrawing.load().then((drawing) => disposed || drawing.startNodeFilm(m, film));
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
  filmParametersOf(physical(material), checked, refuse);
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

/**
 * A promise kept once the film's drawing is loaded (a chunk of its own, fetched the first time a
 * material is made spectral) and holds the material's film, and once the programs a changed film
 * needs are built off the frame: the next render that draws the material builds what its film
 * needs (the table, on the GPU, before the draw) and draws the settled film, so a screenshot
 * awaits this, then renders. A ParameterError for a material this entry has not made spectral.
 */
export async function whenSpectralReady(material: Material): Promise<void> {
  const notSpectral = () =>
    new ParameterError(
      'material',
      'whenSpectralReady: the material is not spectral; expected one spectralIridescence of thin-film-color/webgpu upgraded',
    );
  if (!filmOf(material)) throw notSpectral();
  const drawing = await nodeDrawing.load();
  if (!drawing.drawsNodeFilm(material as PhysicalMaterial)) throw notSpectral();
  await drawing.nodeFilmReady(material as PhysicalMaterial);
}

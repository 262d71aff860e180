/**
 * What draws the WebGPU entry's film, loaded apart from the entry (spectralNodeDrawing.ts) the
 * first time a material is made spectral: the film's nodes, its table and lighting model
 * (nodeFilm.ts), and the data they are computed from (the CIE tables, the lights, the media).
 */
import { filmColorUniforms, releaseFilmColorTextures } from '../film/filmColor.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { type SpectralFilm } from '../meshMaterial/spectralFilm.ts';
import { Vector3 } from 'three';
import { uniform } from 'three/tsl';
import { filmInputs } from './filmInputs.ts';
import { type NodeFilm, addNodeFilm, nodeFilmOf, nodeProgramKey, prepareNodeFilm, updateNodeFilm } from './nodeFilm.ts';
import { type PhysicalMaterial, physical } from './physicalMaterial.ts';
import { buildAhead, newAhead } from './programAhead.ts';

export { setupLightingModel } from './nodeFilm.ts';

/**
 * Starts drawing `film` on `m`: its uniforms and TSL inputs, brought up to the material, and its
 * program key from here on, a changed program built ahead once it has been drawn; the material's
 * version moves, so the next render builds the film.
 */
export function startNodeFilm(m: PhysicalMaterial, film: SpectralFilm): void {
  film.uniforms = { ...filmColorUniforms(), ...filmStackUniforms() };
  film.programKey = nodeProgramKey;
  const f: NodeFilm = {
    film,
    inputs: filmInputs(),
    table: null,
    tint: uniform(new Vector3(1, 1, 1)),
    renderer: null,
    lastDraw: null,
    ahead: newAhead(),
  };
  film.programAhead = () => buildAhead(f, m);
  addNodeFilm(m, f);
  updateNodeFilm(f, m, null);
  m.needsUpdate = true;
}

/** The film's part of `m`'s program key. */
export const nodeFilmKey = (m: PhysicalMaterial, film: SpectralFilm): string => nodeProgramKey(physical(m), film.options);

/** Whether `m` is drawn by this entry's film (made spectral by it). */
export const drawsNodeFilm = (m: PhysicalMaterial): boolean => nodeFilmOf(m) !== undefined;

/** Done when `m`'s next draw builds no program on this thread (prepareNodeFilm); `m` is drawn by this entry's film. */
export const nodeFilmReady = (m: PhysicalMaterial): Promise<void> => prepareNodeFilm(nodeFilmOf(m)!, m);

/** Lets `m`'s film go: its share of the light's textures, and its table. */
export function releaseNodeFilm(m: PhysicalMaterial): void {
  const f = nodeFilmOf(m);
  if (!f) return;
  releaseFilmColorTextures(f.film);
  f.table?.dispose();
  f.table = null;
}

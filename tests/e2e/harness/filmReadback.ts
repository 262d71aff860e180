/**
 * The GPU film read back in the float64 twin's orders, for the browser tests: a GpuFilmSimulation's
 * targets (its public `stateTargets`) read through the renderer, and their texels decoded by the
 * layouts and records the passes write (src/gpuFilmDynamics/flowAtlas.ts, flowLayouts.ts, flowTexels.ts), each
 * field by its name. The decoders are pure, so a test in Node decodes texels read on a page.
 */
import type { WebGLRenderTarget, WebGLRenderer } from 'three';
import { HOLE_RAYS, MAX_HOLES } from '../../../src/physics/filmDynamics/filmHoles.ts';
import { cellTexelIndex } from '../../../src/gpuFilmDynamics/flowAtlas.ts';
import { HOLE_TABLE, holeFrameTexel } from '../../../src/gpuFilmDynamics/flowLayouts.ts';
import { EDGE_VELOCITY, FLOW_FILM, HOLE_ORIGIN, HOLE_RAY } from '../../../src/gpuFilmDynamics/flowTexels.ts';
import type { GpuFilmSimulation } from '../../../src/gpuFilmDynamics/gpuFilmSimulation.ts';
import type { FieldWidth, TexelRecord } from '../../../src/gpu/texelRecord.ts';

/** A target's RGBA float texels, row-major. */
export function readTexels(renderer: WebGLRenderer, target: WebGLRenderTarget): Float32Array {
  const out = new Float32Array(4 * target.width * target.height);
  renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, out);
  return out;
}

/** The float field `name` of the record in texel `texel` of `texels` (records of one texel). */
export function texelFloat<F extends Readonly<Record<string, FieldWidth>>>(
  r: TexelRecord<F>,
  texels: ArrayLike<number>,
  texel: number,
  name: keyof F,
): number {
  return texels[texel * r.floats + r.offsets[name]]!;
}

/** The vector field `name` of the record in texel `texel` of `texels`: its floats in order. */
export function texelVector<F extends Readonly<Record<string, FieldWidth>>>(
  r: TexelRecord<F>,
  texels: ArrayLike<number>,
  texel: number,
  name: keyof F,
): number[] {
  const at = texel * r.floats + r.offsets[name];
  const floats: number[] = [];
  for (let k = 0; k < (r.fields[name] as number); k++) floats.push(texels[at + k]!);
  return floats;
}

/** The film's texels (a FLOW_FILM per cell of a grid of side n) in the twin's cell order: η and Γ (in η0, Γ0) and whether intact. */
export function filmCells(texels: ArrayLike<number>, n: number): { eta: Float32Array; gamma: Float32Array; intact: Uint8Array } {
  const cells = 6 * n * n;
  const [eta, gamma, intact] = [new Float32Array(cells), new Float32Array(cells), new Uint8Array(cells)];
  for (let c = 0; c < cells; c++) {
    const t = cellTexelIndex(n, c);
    eta[c] = texelFloat(FLOW_FILM, texels, t, 'ETA');
    gamma[c] = texelFloat(FLOW_FILM, texels, t, 'GAMMA');
    intact[c] = texelFloat(FLOW_FILM, texels, t, 'INTACT');
  }
  return { eta, gamma, intact };
}

/** The hole table's open holes, in the order they opened: each one's centre and its rays' angular radii (the twin's FilmHole). */
export function openHoles(texels: Float32Array): { center: number[]; radius: number[] }[] {
  const at = (s: number, k: number) => s * HOLE_TABLE.width + k;
  const origin = holeFrameTexel('center');
  return Array.from({ length: MAX_HOLES }, (_, s) => s)
    .filter((s) => texelFloat(HOLE_ORIGIN, texels, at(s, origin), 'OPEN') !== 0)
    .map((s) => ({
      center: texelVector(HOLE_ORIGIN, texels, at(s, origin), 'CENTER'),
      radius: Array.from({ length: HOLE_RAYS }, (_, k) => texelFloat(HOLE_RAY, texels, at(s, k), 'RADIUS')),
    }));
}

/** The simulation's film now: per cell η, Γ and intact; per edge u·n_e (in U), in the twin's edge order; the open holes. */
export function readFilmState(renderer: WebGLRenderer, sim: GpuFilmSimulation) {
  const { film, edgeVelocity, holes } = sim.stateTargets;
  const edges = readTexels(renderer, edgeVelocity);
  return {
    ...filmCells(readTexels(renderer, film), sim.grid.n),
    edgeVelocity: Float32Array.from({ length: sim.grid.edgeCount }, (_, e) => texelFloat(EDGE_VELOCITY, edges, e, 'U')),
    holes: openHoles(readTexels(renderer, holes)),
  };
}

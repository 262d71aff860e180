/**
 * The GPU film read back in the float64 twin's orders, for the browser tests: a GpuFilmSimulation's
 * targets (its public `stateTargets`) read through the renderer, and their texels decoded by the
 * layouts the passes write (src/flow/flowAtlas.ts, src/flow/flowLayouts.ts). The decoders are pure,
 * so a test in Node decodes texels read on a page.
 */
import type { WebGLRenderTarget, WebGLRenderer } from 'three';
import { HOLE_RAYS, MAX_HOLES } from '../../../src/physics/flow/filmHoles.ts';
import { cellTexelIndex } from '../../../src/flow/flowAtlas.ts';
import { HOLE_TABLE, SURFACTANT_SWEEP_TEXEL, holeFrameTexel } from '../../../src/flow/flowLayouts.ts';
import type { GpuFilmSimulation } from '../../../src/flow/gpuFilmSimulation.ts';

/** A target's RGBA float texels, row-major. */
export function readTexels(renderer: WebGLRenderer, target: WebGLRenderTarget): Float32Array {
  const out = new Float32Array(4 * target.width * target.height);
  renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, out);
  return out;
}

/** The film's texels (η, Γ, intact, 0 per cell of a grid of side n) in the twin's cell order: η and Γ (in η0, Γ0) and whether intact. */
export function filmCells(texels: ArrayLike<number>, n: number): { eta: Float32Array; gamma: Float32Array; intact: Uint8Array } {
  const cells = 6 * n * n;
  const [eta, gamma, intact] = [new Float32Array(cells), new Float32Array(cells), new Uint8Array(cells)];
  for (let c = 0; c < cells; c++) {
    const t = 4 * cellTexelIndex(n, c);
    [eta[c], gamma[c], intact[c]] = [texels[t]!, texels[t + 1]!, texels[t + 2]!];
  }
  return { eta, gamma, intact };
}

/** The hole table's open holes, in the order they opened: each one's centre and its rays' angular radii (the twin's FilmHole). */
export function openHoles(texels: Float32Array): { center: number[]; radius: number[] }[] {
  const texel = (s: number, k: number) => texels.subarray(4 * (s * HOLE_TABLE.width + k), 4 * (s * HOLE_TABLE.width + k + 1));
  const center = holeFrameTexel('center');
  return Array.from({ length: MAX_HOLES }, (_, s) => s)
    .filter((s) => texel(s, center)[3] !== 0)
    .map((s) => ({ center: [...texel(s, center).subarray(0, 3)], radius: Array.from({ length: HOLE_RAYS }, (_, k) => texel(s, k)[0]!) }));
}

/** √Σ (b − Ax)² over the cells of a surfactant sweep's texels. */
function residualNorm(texels: Float32Array): number {
  let sum = 0;
  for (let t = SURFACTANT_SWEEP_TEXEL.indexOf('residualSquared'); t < texels.length; t += 4) sum += texels[t]!;
  return Math.sqrt(sum);
}

/**
 * The simulation's film now: per cell η, Γ and intact; per edge u·n_e (in U), in the twin's edge
 * order; the open holes; and the relative residual ‖b − AΓ'‖/‖b − AΓ‖ the last step's surfactant
 * solve reached (0 before a step, or when Γ already solved it).
 */
export function readFilmState(renderer: WebGLRenderer, sim: GpuFilmSimulation) {
  const { film, edgeVelocity, holes, residualSweeps } = sim.stateTargets;
  const edges = readTexels(renderer, edgeVelocity);
  const [initial = 0, reached = 0] = residualSweeps?.map((sweep) => residualNorm(readTexels(renderer, sweep))) ?? [];
  return {
    ...filmCells(readTexels(renderer, film), sim.grid.n),
    edgeVelocity: Float32Array.from({ length: sim.grid.edgeCount }, (_, e) => edges[4 * e]!),
    holes: openHoles(readTexels(renderer, holes)),
    surfactantResidual: initial > 0 ? reached / initial : 0,
  };
}

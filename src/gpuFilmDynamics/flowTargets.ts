import { FloatType, NearestFilter, RGBAFormat, WebGLRenderTarget } from 'three';
import { type AtlasSize, edgeAtlasSize, faceAtlasSize } from './flowAtlas.ts';
import { HOLE_TABLE } from './flowLayouts.ts';

const floatTarget = (size: AtlasSize): WebGLRenderTarget =>
  new WebGLRenderTarget(size.width, size.height, {
    type: FloatType,
    format: RGBAFormat,
    minFilter: NearestFilter,
    magFilter: NearestFilter,
    depthBuffer: false,
  });

/** Two targets of one size: a pass reads one and writes the other, and then they swap. */
export class PingPong {
  private index = 0;
  readonly pair: readonly [WebGLRenderTarget, WebGLRenderTarget];

  constructor(size: AtlasSize) {
    this.pair = [floatTarget(size), floatTarget(size)];
  }

  /** The target that holds the field now. */
  get read(): WebGLRenderTarget {
    return this.pair[this.index]!;
  }

  /** The other target, free to be written. */
  get write(): WebGLRenderTarget {
    return this.pair[1 - this.index]!;
  }

  swap(): void {
    this.index = 1 - this.index;
  }

  /** The first target holds the field again. */
  reset(): void {
    this.index = 0;
  }
}

/** The textures a step reads and writes (RGBA float, one texel per cell, padded cell or edge of a grid of side n). */
export function flowTargets(n: number) {
  const cells = faceAtlasSize(n);
  const padded = faceAtlasSize(n + 2);
  const edges = edgeAtlasSize(n);
  return {
    /** The film, a FLOW_FILM record per cell (flowTexels.ts). */
    film: new PingPong(cells),
    edgeVelocity: floatTarget(edges),
    cellVelocity: floatTarget(cells),
    paddedCellVelocity: floatTarget(padded),
    prediction: floatTarget(edges),
    weights: floatTarget(cells),
    system: floatTarget(cells),
    /** The surfactant solve's sweeps, taking turns: each reads the other's. */
    sweeps: [floatTarget(cells), floatTarget(cells)] as const,
    limiter: floatTarget(cells),
    flux: floatTarget(edges),
    /** The padded film, for sampling h anywhere (the bubble's field and the rims). */
    paddedFilm: floatTarget(padded),
    /** Each row's (face, j) count of cells that opened a hole this step, 6n × 1. */
    ruptureRows: floatTarget({ width: 6 * n, height: 1 }),
    /** The hole table (flowLayouts.ts). */
    holes: new PingPong(HOLE_TABLE),
    /** The steps since no film was left (1 × 1). */
    burst: new PingPong({ width: 1, height: 1 }),
  };
}
export type FlowTargets = ReturnType<typeof flowTargets>;

/** Every target of a step's. */
export const allTargets = (t: FlowTargets): WebGLRenderTarget[] =>
  Object.values(t).flatMap((target) => (target instanceof PingPong ? [...target.pair] : target));

/**
 * What fills the node film's table on the GPU (filmTable.ts): a texture of the grid's texels, each
 * the film's XYZ (or a column of its environment matrix) at the texel's thickness and angle. On WebGPURenderer's WebGPU backend a compute
 * pass fills a storage texture (filmTableCompute.ts); on its WebGL2 backend, which has no compute,
 * a render pass draws a quad into a render target (filmTablePass.ts). Both are half float, which
 * the lookup filters on every backend.
 */
import { type Texture } from 'three';
import { type Node, type Renderer, type UniformNode } from 'three/webgpu';
import { type FloatNode } from './complex.ts';

/** Columns [from, to) of the grid. */
export type TableColumns = readonly [number, number];

/**
 * The grid the table holds: texels along thickness, rows, the thickness of its last column, and
 * its colour planes (its XYZ, or the three columns of its environment matrix), one grid above the
 * other in one texture (rows × planes high).
 */
export interface TableGrid {
  readonly width: UniformNode<'float', number>;
  readonly rows: UniformNode<'float', number>;
  readonly maxThicknessNm: UniformNode<'float', number>;
  readonly planes: UniformNode<'float', number>;
}

/** The XYZ of the texel at (u, v) of colour plane `plane`: u, v in [0, 1] run from the first to the last texel centre of its grid. */
export type TexelXyz = (u: FloatNode, v: FloatNode, plane: Node<'int'>) => Node<'vec3'>;

export interface TableFill {
  /** The texture filled, at the grid's size: the lookup samples it with the GPU's linear filtering. */
  readonly texture: Texture;
  /**
   * Fills the texels of the grid (its size as the grid's uniforms hold it) with `xyz`, by
   * `renderer`: every column, or only `columns` (each [from, to), the rest left as they were);
   * `program` names xyz's program: the same name, the same program. A program not built yet is
   * built here, on this thread.
   */
  fill(renderer: Renderer, program: string, xyz: TexelXyz, columns: readonly TableColumns[] | null): void;
  /** How the fill builds a program ahead of its use, off the frame; none where it builds each in place. */
  readonly offFrame: OffFrameBuild | null;
  dispose(): void;
}

/** A fill's programs built ahead of their use. */
export interface OffFrameBuild {
  /**
   * Builds `program` off the frame (three's compileAsync: the nodes built in slices that yield to
   * the page, the GL program linked in parallel where the context can), so that its fill builds
   * nothing; once however often asked.
   */
  build(renderer: Renderer, program: string, xyz: TexelXyz): Promise<void>;
  /** Whether `program` is built (filled with, or its build done). */
  isBuilt(program: string): boolean;
}

/** Whether `renderer` runs on the WebGPU backend (compute), not the WebGL2 one. */
export const computesOn = (renderer: Renderer): boolean => (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;

/**
 * What fills the node film's table on the GPU (filmTable.ts): a texture of the grid's texels, each
 * the film's XYZ at the texel's thickness and angle. On WebGPURenderer's WebGPU backend a compute
 * pass fills a storage texture (filmTableCompute.ts); on its WebGL2 backend, which has no compute,
 * a render pass draws a quad into a render target (filmTablePass.ts). Both are half float, which
 * the lookup filters on every backend.
 */
import { type Texture } from 'three';
import { type Node, type Renderer, type UniformNode } from 'three/webgpu';
import { type FloatNode } from './complex.ts';

/** The grid the table holds: texels along thickness, rows, the thickness of its last column. */
export interface TableGrid {
  readonly width: UniformNode<'float', number>;
  readonly rows: UniformNode<'float', number>;
  readonly maxThicknessNm: UniformNode<'float', number>;
}

/** The XYZ of the texel at (u, v): u, v in [0, 1] run from the first to the last texel centre. */
export type TexelXyz = (u: FloatNode, v: FloatNode) => Node<'vec3'>;

export interface TableFill {
  /** The texture filled, at the grid's size: the lookup samples it with the GPU's linear filtering. */
  readonly texture: Texture;
  /**
   * Fills every texel of the grid (its size as the grid's uniforms hold it) with `xyz`, by
   * `renderer`; `program` names xyz's program: the same name, the same program.
   */
  fill(renderer: Renderer, program: string, xyz: TexelXyz): void;
  dispose(): void;
}

/** Whether `renderer` runs on the WebGPU backend (compute), not the WebGL2 one. */
export const computesOn = (renderer: Renderer): boolean => (renderer.backend as { isWebGPUBackend?: boolean }).isWebGPUBackend === true;

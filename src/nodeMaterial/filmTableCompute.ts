/**
 * The node film's table filled by compute (WebGPURenderer's WebGPU backend): one invocation per
 * texel, of every colour plane, writes the texel's XYZ into a half-float storage texture (rgba16float: a storage format of
 * core WebGPU, and filterable on every adapter, so the lookup samples it with linear filtering).
 */
import { HalfFloatType, type Texture } from 'three';
import { Fn, float, instanceIndex, int, textureStore, uint, uvec2, vec4 } from 'three/tsl';
import { type ComputeNode, type Renderer, StorageTexture } from 'three/webgpu';
import { type TableFill, type TableGrid, type TexelXyz } from './filmTableFill.ts';
import { KeptPrograms } from './keptPrograms.ts';

export class TableCompute implements TableFill {
  private readonly storage = new StorageTexture(1, 1);
  private readonly kernels = new KeptPrograms<ComputeNode>((node) => node.dispose());

  constructor(private readonly grid: TableGrid) {
    this.storage.type = HalfFloatType;
    // one level: the lookup reads texels and filters between them
    this.storage.generateMipmaps = false;
  }

  get texture(): Texture {
    return this.storage;
  }

  /**
   * None: each kernel is built in place, at its first fill. Built ahead with compileComputeAsync,
   * the first switch to a dispersive film measured no shorter a task on SwiftShader's WebGPU, and
   * far longer to its frame (the pipeline compiled beside the frames drawn meanwhile, on the same CPU).
   */
  readonly offFrame = null;

  fill(renderer: Renderer, program: string, xyz: TexelXyz): void {
    const width = this.grid.width.value;
    const height = this.grid.rows.value * this.grid.planes.value;
    // a 2D texture's depth is 1 (three's types ask for one)
    this.storage.setSize(width, height, 1);
    const node = this.kernelFor(program, xyz);
    node.count = width * height;
    void renderer.compute(node);
  }

  dispose(): void {
    this.storage.dispose();
    this.kernels.clear();
  }

  /** The compute node of the program (kept for the last programs). */
  private kernelFor(program: string, xyz: TexelXyz): ComputeNode {
    const { width, rows } = this.grid;
    // Invocation i is texel (i mod width, i div width), in the plane y div rows; its (u, v) its column and row over the last ones.
    return this.kernels.of(program, () =>
      Fn(() => {
        const x = instanceIndex.mod(uint(width));
        const y = instanceIndex.div(uint(width));
        const plane = y.div(uint(rows));
        const value = xyz(float(x).div(width.sub(1)), float(y.sub(plane.mul(uint(rows)))).div(rows.sub(1)), int(plane));
        textureStore(this.storage, uvec2(x, y), vec4(value, 1)).toWriteOnly();
      })().compute(1),
    );
  }
}

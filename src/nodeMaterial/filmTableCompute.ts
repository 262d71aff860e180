/**
 * The node film's table filled by compute (WebGPURenderer's WebGPU backend): one invocation per
 * texel, of every colour plane, writes the texel's XYZ into a half-float storage texture (rgba16float: a storage format of
 * core WebGPU, and filterable on every adapter, so the lookup samples it with linear filtering).
 */
import { HalfFloatType, type Texture } from 'three';
import { Fn, float, instanceIndex, int, textureStore, uint, uniform, uvec2, vec4 } from 'three/tsl';
import { type ComputeNode, type Renderer, StorageTexture } from 'three/webgpu';
import { type TableColumns, type TableFill, type TableGrid, type TexelXyz } from './filmTableFill.ts';
import { KeptPrograms } from './keptPrograms.ts';

export class TableCompute implements TableFill {
  private readonly storage = new StorageTexture(1, 1);
  private readonly kernels = new KeptPrograms<ComputeNode>((node) => node.dispose());
  /** the columns a dispatch fills: from `first`, `count` of them */
  private readonly columns = { first: uniform(0, 'uint'), count: uniform(1, 'uint') };

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

  fill(renderer: Renderer, program: string, xyz: TexelXyz, columns: readonly TableColumns[] | null): void {
    const width = this.grid.width.value;
    const height = this.grid.rows.value * this.grid.planes.value;
    // a 2D texture's depth is 1 (three's types ask for one)
    this.storage.setSize(width, height, 1);
    const node = this.kernelFor(program, xyz);
    // One dispatch per range of columns: three reads the uniforms and the count at each.
    for (const [from, to] of columns ?? [[0, width]]) {
      this.columns.first.value = from;
      this.columns.count.value = to - from;
      node.count = (to - from) * height;
      void renderer.compute(node);
    }
  }

  dispose(): void {
    this.storage.dispose();
    this.kernels.clear();
  }

  /** The compute node of the program (kept for the last programs). */
  private kernelFor(program: string, xyz: TexelXyz): ComputeNode {
    const { width, rows } = this.grid;
    const { first, count } = this.columns;
    // Invocation i is texel (first + i mod count, i div count), in the plane y div rows; its (u, v) its column and row over the last ones.
    return this.kernels.of(program, () =>
      Fn(() => {
        const x = first.add(instanceIndex.mod(count));
        const y = instanceIndex.div(count);
        const plane = y.div(uint(rows));
        const value = xyz(float(x).div(width.sub(1)), float(y.sub(plane.mul(uint(rows)))).div(rows.sub(1)), int(plane));
        textureStore(this.storage, uvec2(x, y), vec4(value, 1)).toWriteOnly();
      })().compute(1),
    );
  }
}

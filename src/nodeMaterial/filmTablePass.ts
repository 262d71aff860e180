/**
 * The node film's table filled by a render pass (WebGPURenderer's WebGL2 backend, which has no
 * compute): a quad over a half-float render target whose fragment is the texel's XYZ, its (u, v)
 * from the fragment's centre.
 */
import { HalfFloatType, LinearFilter, RenderTarget, type Texture } from 'three';
import { Fn, uv, vec4 } from 'three/tsl';
import { NodeMaterial, QuadMesh, type Renderer } from 'three/webgpu';
import { type TableFill, type TableGrid, type TexelXyz } from './filmTableFill.ts';
import { KeptPrograms } from './keptPrograms.ts';

export class TablePass implements TableFill {
  private readonly target = new RenderTarget(1, 1, {
    type: HalfFloatType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
  private readonly passes = new KeptPrograms<{ readonly quad: QuadMesh; readonly material: NodeMaterial }>((pass) =>
    pass.material.dispose(),
  );

  constructor(private readonly grid: TableGrid) {}

  get texture(): Texture {
    return this.target.texture;
  }

  fill(renderer: Renderer, program: string, xyz: TexelXyz): void {
    this.target.setSize(this.grid.width.value, this.grid.rows.value);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    this.quadFor(program, xyz).render(renderer);
    renderer.setRenderTarget(previous);
  }

  dispose(): void {
    this.target.dispose();
    this.passes.clear();
  }

  /** The quad of the program (kept for the last programs). */
  private quadFor(program: string, xyz: TexelXyz): QuadMesh {
    const { width, rows } = this.grid;
    return this.passes.of(program, () => {
      const material = new NodeMaterial();
      // The fragment's centre in texels, less half a texel, over the texels between the first and last centres.
      material.fragmentNode = Fn(() =>
        vec4(xyz(uv().x.mul(width).sub(0.5).div(width.sub(1)), uv().y.mul(rows).sub(0.5).div(rows.sub(1))), 1),
      )();
      return { quad: new QuadMesh(material), material };
    }).quad;
  }
}

/**
 * The node film's table filled by a render pass (WebGPURenderer's WebGL2 backend, which has no
 * compute): a quad over a half-float render target (every colour plane's grid) whose fragment is the texel's XYZ, its (u, v)
 * from the fragment's centre. The quad is a mesh of its own with a clip-space vertex node, not
 * three's QuadMesh (whose render swaps in a vertex node of its own), so that compileAsync builds
 * the very program the fill draws with.
 */
import {
  BufferGeometry,
  Float32BufferAttribute,
  HalfFloatType,
  LinearFilter,
  Mesh,
  OrthographicCamera,
  RenderTarget,
  type Texture,
} from 'three';
import { Fn, floor, int, positionGeometry, uv, vec4 } from 'three/tsl';
import { NodeMaterial, type Renderer } from 'three/webgpu';
import { type OffFrameBuild, type TableColumns, type TableFill, type TableGrid, type TexelXyz } from './filmTableFill.ts';
import { KeptPrograms } from './keptPrograms.ts';

/** The quad: three's QuadMesh's triangle over clip space and its uv (v = 0 at the top), and the camera it is drawn with (the vertex node ignores it). */
const quadGeometry = new BufferGeometry()
  .setAttribute('position', new Float32BufferAttribute([-1, 3, 0, -1, -1, 0, 3, -1, 0], 3))
  .setAttribute('uv', new Float32BufferAttribute([0, -1, 0, 1, 2, 1], 2));
const quadCamera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);

export class TablePass implements TableFill {
  private readonly target = new RenderTarget(1, 1, {
    type: HalfFloatType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
  private readonly passes = new KeptPrograms<Mesh<BufferGeometry, NodeMaterial>>((quad) => quad.material.dispose());

  constructor(private readonly grid: TableGrid) {}

  get texture(): Texture {
    return this.target.texture;
  }

  fill(renderer: Renderer, program: string, xyz: TexelXyz, columns: readonly TableColumns[] | null): void {
    const height = this.grid.rows.value * this.grid.planes.value;
    this.target.setSize(this.grid.width.value, height);
    const quad = this.passes.of(program, () => this.quad(xyz));
    // Columns by the target's scissor, one draw per range.
    this.target.scissorTest = columns !== null;
    this.onTarget(renderer, () => {
      for (const [from, to] of columns ?? [[0, this.grid.width.value]]) {
        this.target.scissor.set(from, 0, to - from, height);
        renderer.render(quad, quadCamera);
      }
    });
    this.target.scissorTest = false;
  }

  readonly offFrame: OffFrameBuild = {
    // The target is the fill's, so that the program compiled is the one its render asks for.
    build: (renderer, program, xyz) =>
      this.passes.build(
        program,
        () => this.quad(xyz),
        async (quad) => {
          // In a task of its own, not inside the render that found the fill missing: compileAsync
          // runs its first stage at once, which would make that render's task as long as both.
          await new Promise((resolve) => setTimeout(resolve, 0));
          return this.onTarget(renderer, () => renderer.compileAsync(quad, quadCamera));
        },
      ),
    isBuilt: (program) => this.passes.isBuilt(program),
  };

  dispose(): void {
    this.target.dispose();
    this.passes.clear();
  }

  /** `draw`'s result, `renderer` drawing into the table's target meanwhile. */
  private onTarget<T>(renderer: Renderer, draw: () => T): T {
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    try {
      return draw();
    } finally {
      renderer.setRenderTarget(previous);
    }
  }

  /**
   * A quad whose fragment at the texel's centre, less half a texel, over the texels between the
   * first and last centres of its plane's grid (the planes one above the other), is `xyz` there.
   */
  private quad(xyz: TexelXyz): Mesh<BufferGeometry, NodeMaterial> {
    const { width, rows, planes } = this.grid;
    const material = new NodeMaterial();
    material.vertexNode = vec4(positionGeometry.xy, 0, 1);
    material.fragmentNode = Fn(() => {
      const texelRow = uv().y.mul(rows.mul(planes)).sub(0.5).toVar();
      const plane = floor(texelRow.add(0.5).div(rows)).toVar();
      return vec4(xyz(uv().x.mul(width).sub(0.5).div(width.sub(1)), texelRow.sub(plane.mul(rows)).div(rows.sub(1)), int(plane)), 1);
    })();
    const quad = new Mesh(quadGeometry, material);
    quad.frustumCulled = false;
    return quad;
  }
}

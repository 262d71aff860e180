import { Mesh, OrthographicCamera, PlaneGeometry, type ShaderMaterial, type WebGLRenderer } from 'three';

/** The vertex shader of every fullscreen pass: the quad's corners are the clip space's. */
export const FULLSCREEN_VERTEX = 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }';

/**
 * One quad over the whole target, drawn with a material whose vertex shader is FULLSCREEN_VERTEX:
 * the table pass and the float read-backs draw through it.
 */
export class FullscreenPass {
  readonly quad = new Mesh(new PlaneGeometry(2, 2));
  readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);

  /** Draws `material` over the renderer's current target. */
  render(renderer: WebGLRenderer, material: ShaderMaterial): void {
    this.quad.material = material;
    renderer.render(this.quad, this.camera);
  }

  /** Compiles `material` for the renderer's current target without blocking where the GPU compiles in parallel. */
  compileAsync(renderer: WebGLRenderer, material: ShaderMaterial): Promise<unknown> {
    this.quad.material = material;
    return renderer.compileAsync(this.quad, this.camera);
  }

  dispose(): void {
    this.quad.geometry.dispose();
  }
}

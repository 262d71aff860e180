import type { Material } from 'three';

/** The package entry that draws the spectral film with three's WebGPURenderer. */
export const WEBGPU_ENTRY = 'thin-film-color/webgpu';

/** What a material of this entry says when three's WebGPURenderer draws it. */
export const NODE_RENDERER_MESSAGE =
  `three's WebGPURenderer draws this material without the spectral film (it calls none of the material's hooks, so its film is three's own); ` +
  `make it spectral with ${WEBGPU_ENTRY} for WebGPURenderer`;

/** What three's node renderers call on the node material they draw a material with (NodeMaterial.build). */
interface NodeBuild {
  build(builder: unknown): unknown;
}

/**
 * Calls `warn` when three's WebGPURenderer (three/webgpu, on either backend) draws `m`. That
 * renderer draws a classic material through a node material it makes by copying the material's
 * enumerable keys (NodeLibrary.fromMaterial), then builds it (NodeBuilder calls its `build`); it
 * calls none of the hooks the film lives in (onBeforeCompile, the material's onBeforeRender).
 * An enumerable `build` on `m` is copied with the other keys: the node material's build calls
 * `warn`, then its own class's. WebGLRenderer never calls a material's `build`.
 */
export function warnWhereDrawnAsNodes(m: Material, warn: () => void): void {
  Object.defineProperty(m, 'build', {
    configurable: true,
    enumerable: true,
    writable: true,
    value: function build(this: NodeBuild, builder: unknown): unknown {
      warn();
      return (Object.getPrototypeOf(this) as NodeBuild).build.call(this, builder);
    },
  });
}

import type { Camera, Object3D, Scene, WebGLRenderer } from 'three';
import { linkFailures } from '../gpu/linkFailures.ts';

/** Whether the renderer's GPU compiles programs without blocking the page (KHR_parallel_shader_compile). */
export const compilesInParallel = (renderer: WebGLRenderer): boolean => renderer.extensions.has('KHR_parallel_shader_compile');

/**
 * Compiles the programs of a frame that draws `meshes`, without blocking where the GPU compiles in
 * parallel, beside the other compiles a frame waits for (`others`); where three's own check is off
 * (src/view/bubbleRenderer.ts), reports the programs that failed to link once they are compiled.
 * Only the meshes drawn: three compiles hidden meshes too, making a program no frame would use and
 * one a restored context would not make again. Nothing is checked after a loss of the context
 * while they compiled.
 */
export async function compileFramePrograms(
  renderer: WebGLRenderer,
  camera: Camera,
  scene: Scene,
  meshes: readonly Object3D[],
  others: readonly (Promise<unknown> | null)[],
): Promise<void> {
  // A context lost (or lost and restored) while they compile, or lost as they start, has none of these
  // programs, and the programs three lists may be the lost context's, whose names the restored one
  // gives to other objects: the compile after its restore checks its own.
  let lost = renderer.getContext().isContextLost();
  const onLost = () => (lost = true);
  const canvas = renderer.domElement;
  const events = ['webglcontextlost', 'webglcontextrestored'] as const;
  for (const event of events) canvas.addEventListener(event, onLost);
  try {
    await Promise.all([...meshes.map((mesh) => renderer.compileAsync(mesh, camera, scene)), ...others]);
  } finally {
    for (const event of events) canvas.removeEventListener(event, onLost);
  }
  if (!lost && !renderer.debug.checkShaderErrors) for (const failure of linkFailures(renderer)) console.error(failure);
}

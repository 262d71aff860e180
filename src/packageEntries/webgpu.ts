/**
 * The library's WebGPU entry (`thin-film-color/webgpu`): the spectral thin film for three.js's
 * WebGPURenderer (`three/webgpu`, on its WebGPU and its WebGL2 backend), on a
 * MeshPhysicalNodeMaterial or a classic MeshPhysicalMaterial (three.js is a peer dependency). How
 * to use it: docs/material.md.
 */
export {
  type PhysicalMaterial,
  spectralIridescence,
  useSpectralIridescence,
  whenSpectralReady,
} from '../nodeMaterial/spectralNodeMaterial.ts';
export * from './materialOptions.ts';

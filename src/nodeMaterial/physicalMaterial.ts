import { type MeshPhysicalMaterial } from 'three';
import { type MeshPhysicalNodeMaterial } from 'three/webgpu';

/** A material the WebGPU entry makes spectral: a node material, or a classic one WebGPURenderer draws through its node copy. */
export type PhysicalMaterial = MeshPhysicalNodeMaterial | MeshPhysicalMaterial;

/** A physical material as the shared film code reads it (the glTF parameters both kinds hold). */
export const physical = (m: PhysicalMaterial) => m as MeshPhysicalMaterial;

import type { ShaderMaterial } from 'three';

/**
 * Gives a material new defines if they differ, freeing the program of the old ones (three keeps a
 * material's programs until the material is disposed; a disposed material is set up anew on its
 * next draw), so switching modes for an hour holds one program per material, not one per set.
 */
export function setDefines(m: ShaderMaterial, defines: Record<string, number>): void {
  if (JSON.stringify(defines) === JSON.stringify(m.defines)) return;
  m.dispose();
  m.defines = defines;
  m.needsUpdate = true;
}

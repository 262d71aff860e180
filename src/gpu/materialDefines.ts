import type { ShaderMaterial } from 'three';

/**
 * How many sets of defines a material keeps the programs of (three keeps every program a material
 * was drawn with until the material is disposed): a change and its way back, and two more, compile
 * nothing the second time.
 */
export const KEPT_DEFINE_SETS = 4;

/** Per material, the sets of defines (as JSON) whose programs it may hold, the current one first. */
const keptSets = new WeakMap<ShaderMaterial, string[]>();

/**
 * Gives one of the project's own materials (the bubble's, the environment's, the probe's, a table
 * pass) new defines if they differ: a new `version`, as three's materials take a change of
 * program. It keeps the programs of its last `kept` sets; a set beyond them frees them all by
 * `dispose()` (three frees a material's programs only on its `dispose` event), and the material is
 * set up anew on its next draw, so switching settings for an hour holds at most `kept` programs per
 * material, not one per set. Only for materials no one outside the project holds: a user's
 * material (the spectral one, src/meshMaterial/) never fires `dispose` while in use, since its
 * listeners would take it as gone; it keeps its programs until its own `dispose()`, as three's do.
 */
export function setDefines(m: ShaderMaterial, defines: Record<string, number>, kept = KEPT_DEFINE_SETS): void {
  const key = JSON.stringify(defines);
  const current = JSON.stringify(m.defines);
  if (key === current) return;
  // A material made without defines has compiled nothing for them.
  const sets = keptSets.get(m) ?? (Object.keys(m.defines ?? {}).length > 0 ? [current] : []);
  const at = sets.indexOf(key);
  if (at >= 0) sets.splice(at, 1);
  else if (sets.length >= kept) {
    m.dispose();
    sets.length = 0;
  }
  sets.unshift(key);
  keptSets.set(m, sets);
  m.defines = defines;
  m.needsUpdate = true;
}

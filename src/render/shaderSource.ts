/**
 * Assembles GLSL from `shaders/`: every `#include "name.glsl"` is replaced by that file, once
 * (include guards in the files keep repeats harmless). three.js's own `#include <chunk>` lines
 * are left for three to resolve.
 */
const files = import.meta.glob('../../shaders/*.glsl', { query: '?raw', import: 'default', eager: true }) as Record<string, string>;
const byName = new Map(Object.entries(files).map(([path, text]) => [path.slice(path.lastIndexOf('/') + 1), text]));

export function shaderSource(name: string, seen = new Set<string>()): string {
  const text = byName.get(name);
  if (text === undefined) throw new Error(`shaders/${name} does not exist`);
  seen.add(name);
  return text.replace(/^[ \t]*#include\s+"([^"]+)"[ \t]*$/gm, (_, inner: string) => (seen.has(inner) ? '' : shaderSource(inner, seen)));
}

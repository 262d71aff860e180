/**
 * Assembles GLSL from `shaders/` (its folders mirror src/'s roles; a file is named by its base
 * name alone, which is unique across the folders): every `#include "name.glsl"` is replaced by that file, every
 * time (an include may sit in a branch of `#if` that is not compiled, so a later one must not be
 * dropped; include guards in the files keep repeats harmless). three.js's own `#include <chunk>`
 * lines are left for three to resolve.
 */
const files = import.meta.glob<string>('../../shaders/**/*.glsl', { query: '?raw', import: 'default', eager: true });
const byName = new Map<string, string>();
for (const [path, text] of Object.entries(files)) {
  const name = path.slice(path.lastIndexOf('/') + 1);
  if (byName.has(name)) throw new Error(`shaders/: two files are named ${name}`);
  byName.set(name, text);
}

export function shaderSource(name: string, including: readonly string[] = []): string {
  const text = byName.get(name);
  if (text === undefined) throw new Error(`shaders/${name} does not exist`);
  if (including.includes(name)) throw new Error(`shaders/${name} includes itself: ${[...including, name].join(' → ')}`);
  return text.replace(/^[ \t]*#include\s+"([^"]+)"[ \t]*$/gm, (_, inner: string) => shaderSource(inner, [...including, name]));
}

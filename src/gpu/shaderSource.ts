import { FIELDS, THICKNESS_FIELDS } from '../fields/fields.ts';
import { FILM_METHOD_REGISTRY, FILM_METHODS } from '../methods/methods.ts';
import { enumSource } from './enumDefines.ts';

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

/**
 * Files made from a registry rather than written: every registered method's GLSL under its named
 * `#if` on TFC_FILM_MODE, and every thickness field's on TFC_THICKNESS_FIELD.
 */
const GENERATED: Readonly<Record<string, () => string>> = {
  'filmMethod.glsl': () => enumSource('TFC_FILM_MODE', FILM_METHODS, (m) => `#include "${FILM_METHOD_REGISTRY[m].glsl}"`),
  'thicknessField.glsl': () => enumSource('TFC_THICKNESS_FIELD', FIELDS, (f) => `#include "${THICKNESS_FIELDS[f].glsl}"`),
};
for (const name of Object.keys(GENERATED))
  if (byName.has(name)) throw new Error(`shaders/${name} is made from a registry: no file may take its name`);

export function shaderSource(name: string, including: readonly string[] = []): string {
  const text = byName.get(name) ?? GENERATED[name]?.();
  if (text === undefined) throw new Error(`shaders/${name} does not exist`);
  if (including.includes(name)) throw new Error(`shaders/${name} includes itself: ${[...including, name].join(' → ')}`);
  return text.replace(/^[ \t]*#include\s+"([^"]+)"[ \t]*$/gm, (_, inner: string) => shaderSource(inner, [...including, name]));
}

import { FILM_METHOD_REGISTRY, FILM_METHODS } from '../methods/methods.ts';
import { enumSource } from './enumDefines.ts';

/** A GLSL file's text by its base name (`fresnel.glsl`), unique across shaders/'s folders. */
export type GlslFiles = ReadonlyMap<string, string>;

/** Files made from a registry rather than written, by the name they are included by. */
export type GeneratedGlsl = Readonly<Record<string, () => string>>;

/**
 * `base`'s files and those of an `import.meta.glob` result (path → text), by their base name; an
 * error where two share one, or where one takes the name of a generated file.
 */
export function glslFilesByName(
  glob: Readonly<Record<string, string>>,
  generated: GeneratedGlsl = {},
  base: GlslFiles = new Map(),
): GlslFiles {
  const byName = new Map(base);
  for (const [path, text] of Object.entries(glob)) {
    const name = path.slice(path.lastIndexOf('/') + 1);
    if (byName.has(name)) throw new Error(`shaders/: two files are named ${name}`);
    byName.set(name, text);
  }
  for (const name of Object.keys(generated))
    if (byName.has(name)) throw new Error(`shaders/${name} is made from a registry: no file may take its name`);
  return byName;
}

/**
 * The assembler of GLSL from `files` and `generated`: every `#include "name.glsl"` is replaced by
 * that file, every time (an include may sit in a branch of `#if` that is not compiled, so a later
 * one must not be dropped; include guards in the files keep repeats harmless). three.js's own
 * `#include <chunk>` lines are left for three to resolve.
 */
export function glslAssembler(files: GlslFiles, generated: GeneratedGlsl = {}): (name: string) => string {
  const source = (name: string, including: readonly string[]): string => {
    const text = files.get(name) ?? generated[name]?.();
    if (text === undefined) throw new Error(`shaders/${name} does not exist`);
    if (including.includes(name)) throw new Error(`shaders/${name} includes itself: ${[...including, name].join(' → ')}`);
    return text.replace(/^[ \t]*#include\s+"([^"]+)"[ \t]*$/gm, (_, inner: string) => source(inner, [...including, name]));
  };
  return (name) => source(name, []);
}

/** Made from the methods' registry: every registered method's GLSL under its named `#if` on TFC_FILM_MODE. */
export const FILM_METHOD_GLSL: GeneratedGlsl = {
  'filmMethod.glsl': () => enumSource('TFC_FILM_MODE', FILM_METHODS, (m) => `#include "${FILM_METHOD_REGISTRY[m].glsl}"`),
};

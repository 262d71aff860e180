/**
 * The uniforms a GLSL text declares, read from the text itself (the independent side of a test
 * against the TypeScript that sets them: a uniform declared and never set reads 0 on the GPU).
 */

/** The names of the uniforms declared anywhere in `glsl`, `uniform <type> <name>` (an array's name without its size). */
export const declaredUniforms = (glsl: string): string[] => [
  ...new Set([...glsl.matchAll(/^[ \t]*uniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+(\w+)/gm)].map((m) => m[1]!)),
];

import { FILM_METHOD_GLSL, glslAssembler, glslFilesByName } from '../gpu/glslAssembly.ts';

/**
 * The GLSL of the film's colour and its table: shaders/'s physics, methods, film and gpu folders
 * only, so that what draws a film (a material) carries no field's, flow's or bubble's shader.
 */
const FILM_FILES = import.meta.glob<string>('../../shaders/{physics,methods,film,gpu}/*.glsl', {
  query: '?raw',
  import: 'default',
  eager: true,
});

/** The film's GLSL files by name (for an assembler that adds its own: glslAssembly.ts). */
export const FILM_GLSL = glslFilesByName(FILM_FILES, FILM_METHOD_GLSL);

/** A film shader's source with its includes (glslAssembler). */
export const filmShaderSource = glslAssembler(FILM_GLSL, FILM_METHOD_GLSL);

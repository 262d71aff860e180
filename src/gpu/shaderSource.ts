import { FIELDS, THICKNESS_FIELDS } from '../fields/fields.ts';
import { enumSource } from './enumDefines.ts';
import { FILM_METHOD_GLSL, type GeneratedGlsl, glslAssembler, glslFilesByName } from './glslAssembly.ts';

/**
 * Every GLSL file of `shaders/` (its folders mirror src/'s roles; a file is named by its base name
 * alone, which is unique across the folders), for the bubble, the flow and the harness; what
 * draws only a film takes the film's files alone (src/film/filmShaderSource.ts).
 */
const files = import.meta.glob<string>('../../shaders/**/*.glsl', { query: '?raw', import: 'default', eager: true });

/** Files made from a registry rather than written: the methods', and every thickness field's GLSL under its named `#if` on TFC_THICKNESS_FIELD. */
const GENERATED: GeneratedGlsl = {
  ...FILM_METHOD_GLSL,
  'thicknessField.glsl': () => enumSource('TFC_THICKNESS_FIELD', FIELDS, (f) => `#include "${THICKNESS_FIELDS[f].glsl}"`),
};

/** A shader's source with its includes (glslAssembly.ts). */
export const shaderSource = glslAssembler(glslFilesByName(files, GENERATED), GENERATED);

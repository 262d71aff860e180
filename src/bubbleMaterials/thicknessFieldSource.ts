import { FIELDS, type FieldName, THICKNESS_FIELDS } from '../fields/fields.ts';
import type { FieldUniforms } from '../fields/thicknessField.ts';
import { enumDefines } from '../gpu/enumDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { flowFilmDefines } from '../gpuFilmDynamics/flowTexels.ts';

/**
 * The thickness fields as a shader sees them: every registered field's GLSL under its named
 * `#if` (thicknessField.glsl, made from the registry by shaderSource.ts), so a program holds the
 * one that TFC_THICKNESS_FIELD selects (`tfcThicknessAt`), and the uniforms of all of them, set
 * by the selected field's own update (fields.ts's updateFieldUniforms).
 */
export const thicknessFieldSource = (): string => shaderSource('thicknessField.glsl');

/** The selected field's define, and the flow field's film record (how it reads the padded film it samples). */
export const thicknessFieldDefines = (s: { readonly field: FieldName }): Record<string, number> => ({
  ...enumDefines('TFC_THICKNESS_FIELD', FIELDS, s.field),
  ...flowFilmDefines(),
});

export const thicknessFieldUniforms = (): FieldUniforms =>
  Object.assign({}, ...FIELDS.map((name) => THICKNESS_FIELDS[name].uniforms())) as FieldUniforms;

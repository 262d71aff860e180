import { type DataTexture, type Matrix3, ShaderMaterial } from 'three';
import { XYZ_TO_LINEAR_DISPLAY_P3, XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { type FilmSettings, SIDES } from '../settings/filmSettings.ts';
import { type FieldDerived, updateFieldUniforms } from '../fields/fields.ts';
import type { DrawnField } from '../fields/thicknessField.ts';
import { thicknessFieldDefines, thicknessFieldSource, thicknessFieldUniforms } from './thicknessFieldSource.ts';
import { enumDefines } from '../gpu/enumDefines.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { type FilmTableBinding, filmColorDefines, filmColorUniforms, matrix3, updateFilmColorUniforms } from '../film/filmColor.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { filmTablePlanesUniforms } from '../film/filmTableGrid.ts';
import { lightTintUniforms, setLightTintUniform } from '../film/filmLightTint.ts';
import { environmentDefines, environmentUniforms, updateEnvironmentUniforms } from './environmentMaterial.ts';

/** The compile-time switches: a shader holds only the mode, field, sides and options in use. */
export function bubbleDefines(s: FilmSettings, q: FilmQuality): Record<string, number> {
  return {
    ...filmColorDefines(s, q),
    ...thicknessFieldDefines(s),
    ...enumDefines('TFC_SIDES', SIDES, s.sides),
    ...environmentDefines(s),
    TFC_HATCH_OUT_OF_GAMUT: s.space === 'wide-gamut' ? 1 : 0,
  };
}

/** The bubble's ShaderMaterial (shaders/bubbleMaterials/bubble.*.glsl). `updateBubbleUniforms` keeps it current. */
export function createBubbleMaterial(s: FilmSettings, q: FilmQuality): ShaderMaterial {
  return new ShaderMaterial({
    defines: bubbleDefines(s, q),
    uniforms: {
      ...filmColorUniforms(),
      ...filmTablePlanesUniforms(),
      ...filmStackUniforms(),
      ...thicknessFieldUniforms(),
      ...environmentUniforms(),
      uXyzToLinearDisplay: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
      ...lightTintUniforms(),
    },
    vertexShader: shaderSource('bubble.vert.glsl'),
    fragmentShader: thicknessFieldSource() + shaderSource('bubble.frag.glsl'),
  });
}

/**
 * Brings the material up to `s`, its field as `field` draws it (the frame's): `table` for the table
 * mode, `environmentMap` the texture of an HDR `s.env` (the caller shows `sky` until it has arrived).
 */
export function updateBubbleUniforms(
  m: ShaderMaterial,
  s: FilmSettings,
  field: DrawnField<FieldDerived>,
  q: FilmQuality,
  table: FilmTableBinding | null,
  displayIsP3: boolean,
  environmentMap: DataTexture | null,
): void {
  const u = m.uniforms;
  setDefines(m, bubbleDefines(s, q));
  updateFilmColorUniforms(m, s, q, table);
  updateFieldUniforms(u, s, field);
  updateEnvironmentUniforms(m, s, environmentMap);
  setLightTintUniform(u, s.lightTint);
  (u.uXyzToLinearDisplay!.value as Matrix3).set(...(displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB));
}

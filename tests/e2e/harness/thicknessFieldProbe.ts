/**
 * Renders the thickness fields' tfcThicknessAt (shaders/fields/) at given points of the unit sphere into a
 * float target and reads it back, one pixel per point (the parity harness's thickness twin check).
 * An evolving field's film is its simulation's at the settings' time.
 */
import { FULLSCREEN_VERTEX } from '../../../src/gpu/fullscreenPass.ts';
import { ShaderMaterial, type WebGLRenderer } from 'three';
import {
  type FieldName,
  type FieldSettings as ThicknessFieldSettings,
  drawnField,
  updateFieldUniforms,
} from '../../../src/fields/fields.ts';
import { createFieldState } from '../../../src/bubbleMaterials/fieldStates.ts';
import { thicknessFieldDefines, thicknessFieldSource, thicknessFieldUniforms } from '../../../src/bubbleMaterials/thicknessFieldSource.ts';
import { floatRowTexture, renderFloatRow } from '../../../src/gpu/floatRow.ts';

export type FieldSettings = ThicknessFieldSettings & { readonly field: FieldName };

const FRAGMENT = `${thicknessFieldSource()}
uniform sampler2D uPoints;
void main() {
  vec3 p = texelFetch(uPoints, ivec2(gl_FragCoord.xy), 0).xyz;
  gl_FragColor = vec4(tfcThicknessAt(p), 0.0, 0.0, 1.0);
}`;

export function renderThickness(
  renderer: WebGLRenderer,
  points: readonly (readonly [number, number, number])[],
  s: FieldSettings,
): number[] {
  const texture = floatRowTexture(points.map((p) => [...p, 0]));
  const material = new ShaderMaterial({
    defines: thicknessFieldDefines(s),
    uniforms: { uPoints: { value: texture }, ...thicknessFieldUniforms() },
    vertexShader: FULLSCREEN_VERTEX,
    fragmentShader: FRAGMENT,
  });
  const field = drawnField(s);
  updateFieldUniforms(material.uniforms, s, field);
  // An evolving field's film, advanced to the settings' time (at simSpeed 0: its start).
  const state = createFieldState(s.field, renderer);
  state?.advance(material.uniforms, s, field.derived, Infinity);
  const out = renderFloatRow(renderer, material, points.length);
  state?.dispose();
  texture.dispose();
  material.dispose();
  return points.map((_, i) => out[4 * i]!);
}

declare global {
  interface Window {
    /** The shader's thickness at each point, for each field setting. */
    renderThickness?: (points: readonly (readonly [number, number, number])[], s: FieldSettings) => number[];
  }
}

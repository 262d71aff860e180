/**
 * Renders shaders/thicknessField.glsl's thicknessAt at given points of the unit sphere into a
 * float target and reads it back, one pixel per point (the parity harness's thickness twin check).
 */
import {
  DataTexture,
  FloatType,
  Mesh,
  NearestFilter,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  ShaderMaterial,
  WebGLRenderTarget,
  type WebGLRenderer,
} from 'three';
import { FIELDS, type FilmSettings } from '../../../src/render/filmSettings.ts';
import { shaderSource } from '../../../src/render/shaderSource.ts';

export type FieldSettings = Pick<FilmSettings, 'field' | 'thicknessNm' | 'thicknessRangeNm' | 'swirlSpeed' | 'timeSeconds'>;

const FRAGMENT = `${shaderSource('thicknessField.glsl')}
uniform sampler2D uPoints;
void main() {
  vec3 p = texelFetch(uPoints, ivec2(gl_FragCoord.xy), 0).xyz;
  gl_FragColor = vec4(thicknessAt(p), 0.0, 0.0, 1.0);
}`;

export function renderThickness(
  renderer: WebGLRenderer,
  points: readonly (readonly [number, number, number])[],
  s: FieldSettings,
): number[] {
  const count = points.length;
  const data = new Float32Array(4 * count);
  points.forEach((p, i) => data.set([...p, 0], 4 * i));
  const texture = new DataTexture(data, count, 1, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  const material = new ShaderMaterial({
    defines: { TFC_THICKNESS_FIELD: FIELDS.indexOf(s.field) },
    uniforms: {
      uPoints: { value: texture },
      uThicknessNm: { value: s.thicknessNm },
      uThicknessRangeNm: { value: s.thicknessRangeNm },
      uSwirlSpeed: { value: s.swirlSpeed },
      uTimeSeconds: { value: s.timeSeconds },
    },
    vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader: FRAGMENT,
  });
  const quad = new Mesh(new PlaneGeometry(2, 2), material);
  const target = new WebGLRenderTarget(count, 1, { type: FloatType, format: RGBAFormat, depthBuffer: false });
  renderer.setRenderTarget(target);
  renderer.render(quad, new OrthographicCamera(-1, 1, 1, -1, 0, 1));
  const out = new Float32Array(4 * count);
  renderer.readRenderTargetPixels(target, 0, 0, count, 1, out);
  renderer.setRenderTarget(null);
  for (const disposable of [target, texture, material, quad.geometry]) disposable.dispose();
  return points.map((_, i) => out[4 * i]!);
}

declare global {
  interface Window {
    /** The shader's thickness at each point, for each field setting. */
    renderThickness?: (points: readonly (readonly [number, number, number])[], s: FieldSettings) => number[];
  }
}

/**
 * Renders film XYZ through the real shaders (shaders/filmColor.glsl, via shaderSource) into a
 * float target and reads it back: one draw per group, one pixel per case, no colour conversion.
 * In `table` mode the table is built by the app's own FilmTable pass, covering the group's
 * largest thickness (as the bubble's table covers its field's).
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
  WebGLRenderer,
} from 'three';
import { filmColorDefines } from '../../../src/render/bubbleMaterial.ts';
import { DEFAULT_SETTINGS, EXACT_SPECTRAL_BINS } from '../../../src/render/filmSettings.ts';
import { FilmTable } from '../../../src/render/filmTable.ts';
import { shaderSource } from '../../../src/render/shaderSource.ts';
import { spectralBinsTexture } from '../../../src/render/spectralBinsTexture.ts';
import type { ParityGroup, ParityMode } from './parityCase.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#gl');
if (!canvas) throw new Error('parity.html must hold #gl');
const renderer = new WebGLRenderer({ canvas });
const camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
const quad = new Mesh(new PlaneGeometry(2, 2));
const table = new FilmTable();
const materials = new Map<string, ShaderMaterial>();

const FRAGMENT = `${shaderSource('filmColor.glsl')}
uniform sampler2D uInputs; // r: thickness in nm, g: cos θ_i
void main() {
  vec2 film = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0).rg;
  gl_FragColor = vec4(filmXyz(film.x, film.y, false), 1.0);
}`;

function material(mode: ParityMode, g: ParityGroup): ShaderMaterial {
  const key = `${mode}|${g.polarization}`;
  const hit = materials.get(key);
  if (hit) return hit;
  const m = new ShaderMaterial({
    defines: filmColorDefines({ mode, polarization: g.polarization }),
    uniforms: {
      uInputs: { value: null },
      uSpectralBins: { value: null },
      uNOutside: { value: 1 },
      uNFilm: { value: 1.33 },
      uNInside: { value: 1 },
      uFilmTable: { value: null },
      uTableMaxThicknessNm: { value: 1 },
    },
    vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader: FRAGMENT,
  });
  materials.set(key, m);
  return m;
}

function renderGroup(g: ParityGroup, mode: ParityMode): number[][] {
  const count = g.inputs.length;
  const inputs = new Float32Array(4 * count);
  g.inputs.forEach(([thicknessNm, cosIncidence], i) => inputs.set([thicknessNm, cosIncidence, 0, 0], 4 * i));
  const inputTexture = new DataTexture(inputs, count, 1, RGBAFormat, FloatType);
  inputTexture.minFilter = inputTexture.magFilter = NearestFilter;
  inputTexture.needsUpdate = true;
  const m = material(mode, g);
  const u = m.uniforms;
  u.uInputs!.value = inputTexture;
  u.uSpectralBins!.value = spectralBinsTexture(g.illuminant, g.normalization, EXACT_SPECTRAL_BINS);
  u.uNOutside!.value = g.nOutside;
  u.uNFilm!.value = g.nFilm;
  u.uNInside!.value = g.nInside;
  if (mode === 'table') {
    const maxThicknessNm = Math.max(...g.inputs.map(([t]) => t));
    table.update(renderer, { ...DEFAULT_SETTINGS, ...g, field: 'uniform', thicknessNm: maxThicknessNm, mode });
    u.uFilmTable!.value = table.texture;
    u.uTableMaxThicknessNm!.value = table.maxThicknessNm;
  }
  const target = new WebGLRenderTarget(count, 1, { type: FloatType, format: RGBAFormat, depthBuffer: false });
  quad.material = m;
  renderer.setRenderTarget(target);
  renderer.render(quad, camera);
  const out = new Float32Array(4 * count);
  renderer.readRenderTargetPixels(target, 0, 0, count, 1, out);
  renderer.setRenderTarget(null);
  target.dispose();
  inputTexture.dispose();
  return g.inputs.map((_, i) => [out[4 * i]!, out[4 * i + 1]!, out[4 * i + 2]!]);
}

window.renderFilmXyz = (groups, mode) => groups.map((g) => renderGroup(g, mode));
document.body.dataset.ready = 'yes';

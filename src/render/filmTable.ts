import {
  FloatType,
  LinearFilter,
  Mesh,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  ShaderMaterial,
  type Texture,
  type WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { type FilmSettings, TABLE_ROWS, TABLE_SPECTRAL_BINS, TABLE_WIDTH, maxFieldThicknessNm } from './filmSettings.ts';
import { shaderSource } from './shaderSource.ts';
import { spectralBinsTexture } from './spectralBinsTexture.ts';

/** What the table depends on; anything else (the field's animation, exposure, space) leaves it alone. */
export function tableKey(s: FilmSettings): string {
  return JSON.stringify([s.nOutside, s.nFilm, s.nInside, s.illuminant, s.polarization, s.normalization, maxFieldThicknessNm(s)]);
}

/**
 * The `table` method: a GPU pass running shaders/filmTable.glsl fills a float texture with the
 * film's XYZ over (thickness 0..max, cos θ_i 0..1), for light from outside and from inside.
 * It is rebuilt only when `tableKey` changes.
 */
export class FilmTable {
  readonly target = new WebGLRenderTarget(TABLE_WIDTH, 2 * TABLE_ROWS, {
    type: FloatType,
    format: RGBAFormat,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
  private key = '';
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly quad = new Mesh(new PlaneGeometry(2, 2));
  private readonly materials = new Map<string, ShaderMaterial>();
  maxThicknessNm = 1;
  /** Milliseconds the last rebuild took (synced with a 1-pixel read), for the benchmark. */
  lastBuildMs = 0;

  get texture(): Texture {
    return this.target.texture;
  }

  /** Rebuilds the table if a parameter it depends on changed; returns whether it did. */
  update(renderer: WebGLRenderer, s: FilmSettings): boolean {
    const key = tableKey(s);
    if (key === this.key) return false;
    const started = performance.now();
    this.maxThicknessNm = maxFieldThicknessNm(s);
    const material = this.material(s);
    material.uniforms.uSpectralBins!.value = spectralBinsTexture(s.illuminant, s.normalization, TABLE_SPECTRAL_BINS);
    material.uniforms.uNOutside!.value = s.nOutside;
    material.uniforms.uNFilm!.value = s.nFilm;
    material.uniforms.uNInside!.value = s.nInside;
    material.uniforms.uTableMaxThicknessNm!.value = this.maxThicknessNm;
    this.quad.material = material;
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    renderer.render(this.quad, this.camera);
    renderer.readRenderTargetPixels(this.target, 0, 0, 1, 1, new Float32Array(4));
    renderer.setRenderTarget(previous);
    this.lastBuildMs = performance.now() - started;
    this.key = key;
    return true;
  }

  /** Forces a rebuild on the next update (after a lost context). */
  invalidate(): void {
    this.key = '';
  }

  private material(s: FilmSettings): ShaderMaterial {
    const hit = this.materials.get(s.polarization);
    if (hit) return hit;
    const m = new ShaderMaterial({
      defines: {
        POLARIZATION: POLARIZATIONS.indexOf(s.polarization),
        SPECTRAL_BINS: TABLE_SPECTRAL_BINS,
        FILM_TABLE_WIDTH: TABLE_WIDTH,
        FILM_TABLE_ROWS: TABLE_ROWS,
      },
      uniforms: {
        uSpectralBins: { value: null },
        uNOutside: { value: 1 },
        uNFilm: { value: 1.33 },
        uNInside: { value: 1 },
        uTableMaxThicknessNm: { value: 1 },
      },
      vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
      fragmentShader: shaderSource('filmTable.glsl'),
    });
    this.materials.set(s.polarization, m);
    return m;
  }

  dispose(): void {
    this.target.dispose();
    this.quad.geometry.dispose();
    for (const m of this.materials.values()) m.dispose();
    this.materials.clear();
  }
}

import {
  type DataTexture,
  FloatType,
  HalfFloatType,
  LinearFilter,
  Mesh,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  ShaderMaterial,
  type WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { type FilmIndex } from '../physics/filmIndex.ts';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { dispersiveRows, dispersiveRowsTexture } from './dispersiveRows.ts';
import { filmIndexDefines, filmIndexUniforms, updateFilmIndexUniforms } from './filmIndexUniforms.ts';
import { airySeriesRows, airySeriesRowsTexture } from './airySeriesRows.ts';
import { type FilmQuality, spectralBinsFor } from './filmQuality.ts';
import { type FilmSettings, maxFieldThicknessNm } from './filmSettings.ts';
import { filmTableLayoutDefines, filmTableWidth } from './filmTableLayout.ts';
import { setDefines } from './materialDefines.ts';
import { shaderSource } from './shaderSource.ts';
import { airySeriesDefines, releaseSpectralTransformTexture, spectralTransformTexture } from './spectralTransformTexture.ts';
import { releaseSpectralBinsTexture, spectralBinDefines, spectralBinsTexture } from './spectralBinsTexture.ts';

/** What the table depends on; anything else (the field's animation, exposure, space) leaves it alone. */
export function tableKey(s: FilmSettings): string {
  return JSON.stringify([s.nOutside, s.nFilm, s.nInside, s.illuminant, s.polarization, s.normalization, maxFieldThicknessNm(s)]);
}

/**
 * The table's texel type: float where the GPU can render to float (EXT_color_buffer_float) and
 * filter it (OES_texture_float_linear), else half float, which WebGL2 always filters and renders
 * to with EXT_color_buffer_half_float (or EXT_color_buffer_float).
 */
export function tableTexelType(renderer: WebGLRenderer, precision: FilmQuality['tablePrecision']): typeof FloatType | typeof HalfFloatType {
  const e = renderer.extensions;
  return precision === 'auto' && e.has('EXT_color_buffer_float') && e.has('OES_texture_float_linear') ? FloatType : HalfFloatType;
}

/** A coarse table has this many times fewer texels along each side than the full one. */
const COARSE_DIVISOR = 4;

/**
 * The `table` method: a GPU pass running shaders/filmTable.glsl fills a float texture with the
 * film's XYZ over (thickness 0..max, cos θ_i 0..1), for light from outside and from inside, laid
 * out as `quality.table` says. It is rebuilt only when `tableKey` changes.
 *
 * A `quick` update (the app's frames after a change) fills only a coarse grid, 1/16 of the
 * texels, in the texture's lower left corner, so the next frame shows the change at once; the
 * next update, quick or not, fills the full grid. Without `quick` (the first table, tests,
 * screenshots) the full grid is built at once.
 */
export class FilmTable {
  private readonly target: WebGLRenderTarget;
  /** What the texture holds: the settings' tableKey ('' for nothing) and whether on the coarse grid. */
  private shown = { key: '', coarse: false };
  private grid = { width: 1, rows: 1 };
  private readonly camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly quad = new Mesh(new PlaneGeometry(2, 2));
  /** The table pass: one program for every polarisation (a uniform), so changing it compiles nothing. */
  private readonly pass = new ShaderMaterial({
    uniforms: {
      uSpectralBins: { value: null },
      uSpectralTransform: { value: null },
      uAirySeriesRows: { value: null },
      uDispersiveRows: { value: null },
      uPolarization: { value: 0 },
      uNOutside: { value: 1 },
      ...filmIndexUniforms(),
      uNInside: { value: 1 },
      uTableMaxThicknessNm: { value: 1 },
      uFilmTableWidth: { value: 1 },
      uFilmTableRows: { value: 1 },
    },
    vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader: shaderSource('filmTable.glsl'),
  });
  /** The series' terms per row, from the reference (src/render/airySeriesRows.ts). */
  /**
   * The per-row terms: the series' C₀, B, q (airySeriesRows.ts), or for a dispersive film the Fresnel
   * terms per row and bin (dispersiveRows.ts). One texture, remade when the kind changes, so a
   * dispersive film holds no more GPU objects than a constant one.
   */
  private rows: { texture: DataTexture; dispersive: boolean };
  maxThicknessNm = 1;
  /** Milliseconds the last full build took (synced with a 1-pixel read), and how many there were: for the benchmark. */
  lastBuildMs = 0;
  builds = 0;

  constructor(private readonly quality: FilmQuality) {
    this.rows = { texture: airySeriesRowsTexture(quality.table), dispersive: false };
    this.target = new WebGLRenderTarget(1, 2 * quality.table.rows, {
      format: RGBAFormat,
      minFilter: LinearFilter,
      magFilter: LinearFilter,
      depthBuffer: false,
    });
  }

  /** Whether the texture holds a coarse table: another update will make it full. */
  get coarse(): boolean {
    return this.shown.coarse;
  }

  /** Points a material that looks the table up (shaders/filmColor.glsl, table mode) at it. */
  bind(uniforms: ShaderMaterial['uniforms']): void {
    uniforms.uFilmTable!.value = this.target.texture;
    uniforms.uTableMaxThicknessNm!.value = this.maxThicknessNm;
    uniforms.uFilmTableWidth!.value = this.grid.width;
    uniforms.uFilmTableRows!.value = this.grid.rows;
  }

  /** Brings the table up to date with the settings (coarsely at first if `quick`); returns whether it drew. */
  update(renderer: WebGLRenderer, s: FilmSettings, quick = false): boolean {
    const key = tableKey(s);
    if (key === this.shown.key && !this.shown.coarse) return false;
    const coarse = quick && this.shown.key !== '' && key !== this.shown.key;
    const started = performance.now();
    const layout = this.quality.table;
    this.maxThicknessNm = maxFieldThicknessNm(s);
    const full = { width: filmTableWidth(layout, this.maxThicknessNm), rows: layout.rows };
    this.grid = coarse ? { width: Math.max(2, Math.ceil(full.width / COARSE_DIVISOR)), rows: Math.ceil(full.rows / COARSE_DIVISOR) } : full;
    this.draw(renderer, s, full);
    this.shown = { key, coarse };
    if (!coarse) {
      this.lastBuildMs = performance.now() - started;
      this.builds++;
    }
    return true;
  }

  /** Runs the pass over the grid (the lower left corner of the texture, sized for `full`, if coarse). */
  private draw(renderer: WebGLRenderer, s: FilmSettings, full: { width: number; rows: number }): void {
    const type = tableTexelType(renderer, this.quality.tablePrecision);
    if (this.target.texture.type !== type) {
      this.target.dispose(); // reallocated at the new type on the next render
      this.target.texture.type = type;
    }
    if (this.target.width !== full.width) this.target.setSize(full.width, 2 * full.rows);
    this.target.viewport.set(0, 0, this.grid.width, 2 * this.grid.rows);
    const bins = spectralBinsFor(s.nFilm, this.quality, this.quality.table.spectralBins);
    const material = this.material(s.nFilm, bins);
    const u = material.uniforms;
    u.uSpectralBins!.value = spectralBinsTexture(s.illuminant, s.normalization, bins, this);
    u.uSpectralTransform!.value = spectralTransformTexture(s.illuminant, s.normalization, this);
    // A dispersive film is filled from the bins, with their terms per row (shaders/filmTable.glsl).
    const rowLayout = { ...this.quality.table, rows: this.grid.rows, spectralBins: bins };
    const dispersive = typeof s.nFilm !== 'number';
    if (this.rows.dispersive !== dispersive) {
      this.rows.texture.dispose();
      const texture = dispersive
        ? dispersiveRowsTexture({ ...this.quality.table, spectralBins: bins })
        : airySeriesRowsTexture(this.quality.table);
      this.rows = { texture, dispersive };
    }
    const data = this.rows.texture.image.data as Float32Array;
    if (typeof s.nFilm === 'number') airySeriesRows({ ...s, nFilm: s.nFilm }, rowLayout, data);
    else dispersiveRows(s, rowLayout, data);
    this.rows.texture.needsUpdate = true;
    u.uDispersiveRows!.value = this.rows.texture;
    u.uAirySeriesRows!.value = this.rows.texture;
    u.uPolarization!.value = POLARIZATIONS.indexOf(s.polarization);
    u.uNOutside!.value = s.nOutside;
    updateFilmIndexUniforms(u, s.nFilm);
    u.uNInside!.value = s.nInside;
    u.uTableMaxThicknessNm!.value = this.maxThicknessNm;
    u.uFilmTableWidth!.value = this.grid.width;
    u.uFilmTableRows!.value = this.grid.rows;
    this.quad.material = material;
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    renderer.render(this.quad, this.camera);
    renderer.readRenderTargetPixels(this.target, 0, 0, 1, 1, type === FloatType ? new Float32Array(4) : new Uint16Array(4));
    renderer.setRenderTarget(previous);
    // The pass reads the light's textures only while it draws: let go of them until the next build.
    releaseSpectralBinsTexture(this);
    releaseSpectralTransformTexture(this);
  }

  /** Forces a rebuild on the next update (after a lost context). */
  invalidate(): void {
    this.shown = { key: '', coarse: false };
  }

  private material(index: FilmIndex, bins: number): ShaderMaterial {
    setDefines(this.pass, {
      ...filmIndexDefines(index),
      TFC_POLARIZATION_UNIFORM: 1,
      ...spectralBinDefines(bins, this.quality.spectralTailTolerance),
      ...filmTableLayoutDefines(this.quality.table),
      ...airySeriesDefines(),
    });
    return this.pass;
  }

  dispose(): void {
    this.target.dispose();
    this.quad.geometry.dispose();
    this.pass.dispose();
    this.rows.texture.dispose();
    releaseSpectralBinsTexture(this);
    releaseSpectralTransformTexture(this);
  }
}

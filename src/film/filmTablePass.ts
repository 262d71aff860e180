import { type DataTexture, FloatType, HalfFloatType, LinearFilter, RGBAFormat, type WebGLRenderer, WebGLRenderTarget } from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { enumCode } from '../gpu/enumDefines.ts';
import { FullscreenPass } from '../gpu/fullscreenPass.ts';
import type { FilmQuality } from '../settings/filmQuality.ts';
import type { FilmOptics } from '../settings/filmSettings.ts';
import { type FilmTableLayout, filmTableWidth } from '../settings/filmTableLayout.ts';
import { airySeriesRows, airySeriesRowsTexture } from './airySeriesRows.ts';
import { dispersiveRowsKey, dispersiveRowsTexture } from './dispersiveRows.ts';
import { dispersiveRowsOf, dispersiveRowsReady, dispersiveRowsWhenReady } from './dispersiveRowsStore.ts';
import { fillGpu, updateFilmMediaUniforms, updateFilmStackUniforms } from './filmFillGpu.ts';
import { type FilmTableGrid, setFilmTableGridUniforms } from './filmTableGrid.ts';
import { type StackedSettings, releaseFilmStackTexture } from './filmStack.ts';
import { bindSpectralBins, releaseSpectralBinsTexture, spectralBinsTexture } from './spectralBinsTexture.ts';
import {
  releaseSpectralTransformTexture,
  spectralTransformReady,
  spectralTransformTexture,
  spectralTransformWhenReady,
} from './spectralTransformTexture.ts';
import type { SpectralLight, PlaneCount } from '../physics/spectralWeights.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { TablePassPrograms } from './tablePassPrograms.ts';

/** Columns [from, to) of a grid. */
export type TableColumns = readonly [number, number];

/**
 * The table's texel type: float where the GPU can render to float (EXT_color_buffer_float) and
 * filter it (OES_texture_float_linear), else half float, which WebGL2 always filters and renders
 * to with EXT_color_buffer_half_float (or EXT_color_buffer_float).
 */
export function tableTexelType(renderer: WebGLRenderer, precision: FilmQuality['tablePrecision']): typeof FloatType | typeof HalfFloatType {
  const e = renderer.extensions;
  return precision === 'auto' && e.has('EXT_color_buffer_float') && e.has('OES_texture_float_linear') ? FloatType : HalfFloatType;
}

/**
 * A target for a table in `planes` colour planes (filmPlanes: one texture each, written by one draw),
 * `height` texels high until the pass sizes (and types) it to the grid it draws.
 */
export const tableTarget = (height: number, planes: PlaneCount = 1): WebGLRenderTarget =>
  new WebGLRenderTarget(1, height, {
    format: RGBAFormat,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
    count: planes,
  });

/**
 * The table pass: shaders/film/filmTable.glsl drawn over a grid of the film table (or some of its
 * columns) in a target, filling it with the film's XYZ over (thickness 0..max, cos θ_i 0..1), for
 * light from outside and from inside. It holds the light's textures it reads from its first draw
 * for a light until `releaseLight`, and the per-row terms, computed once for the bands of one table.
 */
export class FilmTablePass {
  private readonly programs: TablePassPrograms;
  private fullscreen = new FullscreenPass();
  /**
   * The per-row terms: the series' C₀, B, q (airySeriesRows.ts), or for a dispersive film the Fresnel
   * terms per row and bin (dispersiveRows.ts). One texture, remade when the kind changes, so a
   * dispersive film holds no more GPU objects than a constant one.
   */
  private rows: { texture: DataTexture; dispersive: boolean };
  /** What the row terms were last computed for (dispersiveRowsKey of the film and the grid's rows). */
  private rowsFor = '';

  constructor(private readonly quality: FilmQuality) {
    this.programs = new TablePassPrograms(quality);
    this.rows = { texture: airySeriesRowsTexture(quality.table), dispersive: false };
  }

  /**
   * The full grid for the settings over thicknesses up to `maxThicknessNm`: its width follows that
   * range and the film's index (a stack's: the sum of its field-following films'). A stack that does
   * not follow the field is the same at every thickness: two equal columns, which any lookup reads alike.
   */
  fullGrid(s: FilmOptics & StackedSettings, maxThicknessNm: number): FilmTableGrid {
    const layout = this.quality.table;
    const index = fillGpu(s).fieldIndex(s, this.programs.bins(s));
    const width = index === null ? 2 : filmTableWidth(layout, maxThicknessNm, index);
    return { width, rows: layout.rows, maxThicknessNm };
  }

  /** The layout of the row terms of `grid` for `s`: the table's, with the grid's rows and the settings' bins. */
  private rowLayout(s: FilmOptics, grid: FilmTableGrid): FilmTableLayout {
    return { ...this.quality.table, rows: grid.rows, spectralBins: this.programs.bins(s) };
  }

  /** What a build of `s` over `grids` is computed from, each asked by `light` (the light's transform) or `rows` (a dispersive film's row terms of a grid). */
  private inputs<T>(
    s: FilmOptics,
    grids: readonly FilmTableGrid[],
    light: (l: SpectralLight, planes: PlaneCount) => T,
    rows: (key: string) => T,
  ): T[] {
    const dispersive = fillGpu(s).dispersiveRows ? grids.map((g) => rows(dispersiveRowsKey(s, this.rowLayout(s, g)))) : [];
    return [light(s, filmPlanes(s)), ...dispersive];
  }

  /** Whether the light's transform and, for a dispersive film, the row terms of each grid are at hand (each asked of its worker at once). */
  inputsReady(s: FilmOptics, grids: readonly FilmTableGrid[]): boolean {
    return this.inputs(s, grids, spectralTransformReady, dispersiveRowsReady).every(Boolean);
  }

  /** A promise kept once what inputsReady asks for is at hand, computed in the workers (or here, where there are none). */
  async inputsWhenReady(s: FilmOptics, grids: readonly FilmTableGrid[]): Promise<void> {
    await Promise.all(this.inputs(s, grids, spectralTransformWhenReady, dispersiveRowsWhenReady));
  }

  /**
   * Runs the pass for `s` over `grid` in `target` (sized to it), over the column ranges [from, to) if
   * given (the rest of the texture is kept), through `time`, which draws it and may time it. A film
   * in three colour planes (filmPlanes) needs a target of three textures (tableTarget), all drawn at once.
   */
  draw(
    renderer: WebGLRenderer,
    s: FilmOptics,
    target: WebGLRenderTarget,
    grid: FilmTableGrid,
    columns: readonly TableColumns[] | null,
    time: (pass: () => void) => void = (pass) => pass(),
  ): void {
    const planes = filmPlanes(s);
    if (target.textures.length !== planes)
      throw new Error(`FilmTablePass: a table in ${planes} colour planes drawn into a target of ${target.textures.length}`);
    const type = tableTexelType(renderer, this.quality.tablePrecision);
    if (target.texture.type !== type) {
      target.dispose(); // reallocated at the new type on the next render
      for (const t of target.textures) t.type = type;
    }
    if (target.width !== grid.width || target.height !== 2 * grid.rows) target.setSize(grid.width, 2 * grid.rows);
    const material = this.programs.material(s);
    const u = material.uniforms;
    bindSpectralBins(u, s, this.programs.bins(s), this, planes);
    u.uSpectralTransform!.value = spectralTransformTexture(s, this, planes);
    // A stack of films is filled by its recursion per bin; a dispersive film is filled from the bins, with their terms per row (shaders/film/filmTable.glsl).
    this.updateRows(s, grid);
    u.uDispersiveRows!.value = this.rows.texture;
    u.uAirySeriesRows!.value = this.rows.texture;
    u.uPolarization!.value = enumCode('TFC_POLARIZATION', POLARIZATIONS, s.polarization);
    updateFilmMediaUniforms(u, s);
    updateFilmStackUniforms(u, s, this.programs.bins(s), this);
    setFilmTableGridUniforms(u, grid);
    const previous = renderer.getRenderTarget();
    target.scissorTest = true;
    time(() => {
      for (const [from, to] of columns ?? [[0, grid.width]]) {
        target.scissor.set(from, 0, to - from, 2 * grid.rows);
        renderer.setRenderTarget(target); // three takes the target's scissor as it binds it
        this.fullscreen.render(renderer, material);
      }
    });
    renderer.setRenderTarget(previous);
  }

  /** Lets go of the light's textures: the pass reads them only while it draws, and a table built band by band keeps them until its last band. */
  releaseLight(): void {
    releaseSpectralBinsTexture(this);
    releaseSpectralTransformTexture(this);
    releaseFilmStackTexture(this);
  }

  /**
   * The per-row terms for `s` on `grid` (computed in float64 on the CPU: a dispersive film's in a
   * worker, dispersiveRowsStore.ts, or here if not at hand), unless the texture holds them already.
   */
  private updateRows(s: FilmOptics, grid: FilmTableGrid): void {
    const rowLayout = this.rowLayout(s, grid);
    const rowsFor = dispersiveRowsKey(s, rowLayout);
    if (rowsFor === this.rowsFor) return;
    this.rowsFor = rowsFor;
    const { dispersiveRows: dispersive } = fillGpu(s);
    if (this.rows.dispersive !== dispersive) {
      this.rows.texture.dispose();
      const texture = dispersive
        ? dispersiveRowsTexture({ ...rowLayout, rows: this.quality.table.rows })
        : airySeriesRowsTexture(this.quality.table);
      this.rows = { texture, dispersive };
    }
    const data = this.rows.texture.image.data as Float32Array;
    if (dispersive) data.set(dispersiveRowsOf(rowsFor));
    else airySeriesRows(s, rowLayout, data);
    this.rows.texture.needsUpdate = true;
  }

  /**
   * Compiles the pass for `s` and `target`'s kind of target without blocking where the GPU compiles
   * in parallel (KHR_parallel_shader_compile), and meanwhile makes the light's textures for `s` on
   * this thread (the series' transform is an FFT): before a first frame, the two overlap.
   */
  async prepare(renderer: WebGLRenderer, s: FilmOptics, target: WebGLRenderTarget): Promise<void> {
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(target); // three picks a program by its target (no tone mapping into a texture)
    const compiled = this.fullscreen.compileAsync(renderer, this.programs.material(s));
    renderer.setRenderTarget(previous);
    spectralBinsTexture(s, this.programs.bins(s), this, filmPlanes(s));
    spectralTransformTexture(s, this, filmPlanes(s));
    await compiled;
  }

  /** What picks the pass's program for `s`: a change of it needs another program. */
  passKey(s: FilmOptics): string {
    return this.programs.key(s);
  }

  /**
   * Draws in GPU objects of its own (after a lost context): the lost context's quad and row texture
   * are let go, not disposed (see FilmTable.invalidate).
   */
  invalidate(): void {
    this.fullscreen = new FullscreenPass();
    this.rows = { texture: airySeriesRowsTexture(this.quality.table), dispersive: false };
    this.rowsFor = ''; // its row terms were the lost context's too
  }

  dispose(): void {
    this.fullscreen.dispose();
    this.programs.dispose();
    this.rows.texture.dispose();
    this.releaseLight();
  }
}

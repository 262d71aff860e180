import {
  type DataTexture,
  FloatType,
  HalfFloatType,
  LinearFilter,
  RGBAFormat,
  ShaderMaterial,
  type WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { dispersiveRowsKey, dispersiveRowsTexture } from './dispersiveRows.ts';
import { dispersiveRowsOf, dispersiveRowsReady } from './dispersiveRowsStore.ts';
import {
  type FilmMedia,
  filmIndexMax,
  filmMediaDefines,
  filmMediaUniforms,
  isDispersiveFilm,
  updateFilmMediaUniforms,
} from './filmMedia.ts';
import { enumCode, enumConstants } from '../gpu/enumDefines.ts';
import { airySeriesRows, airySeriesRowsTexture } from './airySeriesRows.ts';
import { type FilmQuality, spectralBinsFor } from '../settings/filmQuality.ts';
import { type FilmSettings } from '../settings/filmSettings.ts';
import { maxFieldThicknessNm } from '../fields/fields.ts';
import { type FilmTableLayout, filmTableLookupColumns, filmTableWidth } from '../settings/filmTableLayout.ts';
import { filmTableLayoutDefines } from './filmTableDefines.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { FULLSCREEN_VERTEX, FullscreenPass } from '../gpu/fullscreenPass.ts';
import {
  airySeriesDefines,
  releaseSpectralTransformTexture,
  spectralTransformReady,
  spectralTransformTexture,
} from './spectralTransformTexture.ts';
import { releaseSpectralBinsTexture, spectralBinDefines, spectralBinsTexture } from './spectralBinsTexture.ts';
import { type PassKind, TableBandBudget } from './tableBandBudget.ts';
import { KEPT_PASSES, TABLE_PASS_NAME } from './keptPasses.ts';
import { GpuTimer } from '../gpu/gpuTimer.ts';

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

const passKind = (s: FilmSettings): PassKind => (isDispersiveFilm(s) ? 'dispersive' : 'constant');

/**
 * Runs `pass` into `target` (bound) and waits for it: a 1-pixel read at column `x` before it (the
 * GPU's earlier work done, the frames queued included) and after it; returns when the pass began
 * and its milliseconds.
 */
function syncTimed(renderer: WebGLRenderer, target: WebGLRenderTarget, x: number, pass: () => void): { began: number; ms: number } {
  const pixel = target.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  renderer.readRenderTargetPixels(target, x, 0, 1, 1, pixel);
  const began = performance.now();
  pass();
  renderer.readRenderTargetPixels(target, x, 0, 1, 1, pixel);
  return { began, ms: performance.now() - began };
}

interface Grid {
  readonly width: number;
  readonly rows: number;
}

/** Columns [from, to) of a grid. */
type Columns = readonly [number, number];

/** A table pass (shaders/film/filmTable.glsl) with no defines yet. */
const tablePass = (): ShaderMaterial =>
  new ShaderMaterial({
    name: TABLE_PASS_NAME,
    uniforms: {
      uSpectralBins: { value: null },
      uSpectralTransform: { value: null },
      uAirySeriesRows: { value: null },
      uDispersiveRows: { value: null },
      uPolarization: { value: 0 },
      ...filmMediaUniforms(),
      uTableMaxThicknessNm: { value: 1 },
      uFilmTableWidth: { value: 1 },
      uFilmTableRows: { value: 1 },
    },
    vertexShader: FULLSCREEN_VERTEX,
    fragmentShader: shaderSource('filmTable.glsl'),
  });

/**
 * The `table` method: a GPU pass running shaders/film/filmTable.glsl fills a float texture with the
 * film's XYZ over (thickness 0..max, cos θ_i 0..1), for light from outside and from inside, laid
 * out as `quality.table` says. It is rebuilt only when `tableKey` changes.
 *
 * A `quick` update (the app's frames) that finds the settings changed fills a coarse grid (at
 * most 1/16 of the texels) in a small texture of its own, so the next frame shows the change at
 * once; the quick updates after it fill the full grid band by band, one band per frame, while the
 * coarse one is shown, and the full one is shown once complete. Bands and the coarse grid are
 * sized by the pass's measured cost so that each fits in a share of a frame (TableBandBudget). A
 * new light's spectral transform is computed in a Web Worker: until it arrives, quick updates keep
 * the table shown (the previous light's). Without `quick` (tests, screenshots, the benchmark's
 * timed builds) the full grid is built at once.
 */
export class FilmTable {
  private target: WebGLRenderTarget;
  private coarseTarget: WebGLRenderTarget;
  /** What is shown: the settings' tableKey ('' for nothing) and whether from the coarse texture. */
  private shown = { key: '', coarse: false };
  /** The full grid being built behind a coarse one: its settings and the columns done. */
  private building: { readonly s: FilmSettings; columns: number } | null = null;
  /** Whether quick updates wait for a new light's transform (the table shown is for other settings). */
  private waiting = false;
  private readonly budget = new TableBandBudget();
  /** Whether the last table draw was in the app's frame before (not across frames that drew none): the time between is a frame's. */
  private drawsFollow = false;
  /** Times the app's table draws on the GPU (null where it cannot; undefined until the first). */
  private timer: GpuTimer | null | undefined;
  private shownGrid: Grid = { width: 1, rows: 1 };
  private fullscreen = new FullscreenPass();
  /**
   * The table pass, the last used first, one per set of defines (KEPT_PASSES at most): one program
   * for every polarisation (a uniform), so changing it compiles nothing.
   */
  private readonly passes: ShaderMaterial[] = [];
  /**
   * The per-row terms: the series' C₀, B, q (airySeriesRows.ts), or for a dispersive film the Fresnel
   * terms per row and bin (dispersiveRows.ts). One texture, remade when the kind changes, so a
   * dispersive film holds no more GPU objects than a constant one.
   */
  private rows: { texture: DataTexture; dispersive: boolean };
  /** What the row terms were last computed for (the settings' tableKey and the grid's rows): the bands of one table compute them once. */
  private rowsFor = '';
  maxThicknessNm = 1;
  /** Milliseconds the last full build at once took (synced with a 1-pixel read), and how many full tables there were: for the benchmark. */
  lastBuildMs = 0;
  builds = 0;
  /** Texels the pass has drawn since the table was made, every build and band counted: what a change costs, whatever the GPU. */
  texelsDrawn = 0;

  constructor(private readonly quality: FilmQuality) {
    this.rows = { texture: airySeriesRowsTexture(quality.table), dispersive: false };
    this.target = this.newTarget(2 * quality.table.rows);
    this.coarseTarget = this.newTarget(2);
  }

  private newTarget(height: number): WebGLRenderTarget {
    return new WebGLRenderTarget(1, height, { format: RGBAFormat, minFilter: LinearFilter, magFilter: LinearFilter, depthBuffer: false });
  }

  /**
   * Whether the table shown is the coarse one, or another settings' while a quick update waits for
   * the light's transform: more updates will make it the full one for the settings.
   */
  get coarse(): boolean {
    return this.shown.coarse || this.waiting;
  }

  /** Points a material that looks the table up (shaders/film/filmColor.glsl, table mode) at it. */
  bind(uniforms: ShaderMaterial['uniforms']): void {
    uniforms.uFilmTable!.value = (this.shown.coarse ? this.coarseTarget : this.target).texture;
    uniforms.uTableMaxThicknessNm!.value = this.maxThicknessNm;
    uniforms.uFilmTableWidth!.value = this.shownGrid.width;
    uniforms.uFilmTableRows!.value = this.shownGrid.rows;
  }

  /**
   * Brings the table up to date with the settings: at once, or if `quick` by one step (a coarse
   * table for new settings, else the next band of the full one); returns whether what `bind` binds changed.
   */
  update(renderer: WebGLRenderer, s: FilmSettings, quick = false): boolean {
    const key = tableKey(s);
    this.waiting = false;
    this.timer?.poll();
    if (!quick) {
      this.drawsFollow = false;
      if (key === this.shown.key && !this.shown.coarse) return false;
      this.building = null;
      this.buildFull(renderer, s);
      this.show(key, false);
      return true;
    }
    const kind = passKind(s);
    if (key !== this.shown.key) {
      const full = this.fullGrid(s);
      const divisor = this.budget.coarseDivisor(kind, full.width * 2 * full.rows);
      const grid = { width: Math.max(2, Math.ceil(full.width / divisor)), rows: Math.max(2, Math.ceil(full.rows / divisor)) };
      // A table shown (the first is not waited for) stays until what Web Workers compute for the
      // new one is at hand: the light's transform, and a dispersive film's row terms for both grids.
      if (this.shown.key !== '' && !this.inputsReady(s, [grid, full])) {
        this.waiting = true;
        this.drawsFollow = false; // the frames meanwhile draw no table: they are not timed
        return false;
      }
      this.building = { s, columns: 0 };
      this.timedDraw(renderer, s, this.coarseTarget, grid, [0, grid.width]);
      this.show(key, true, grid);
      return true;
    }
    if (!this.shown.coarse || !this.building) return false;
    const b = this.building;
    const grid = this.fullGrid(b.s);
    const from = b.columns;
    b.columns += this.budget.bandColumns(kind, 2 * grid.rows, grid.width, grid.width - from);
    const last = b.columns === grid.width;
    if (last) this.building = null; // the last band lets go of the light's textures
    this.timedDraw(renderer, b.s, this.target, grid, [from, b.columns]);
    if (!last) return false;
    this.drawsFollow = false;
    this.show(key, false);
    return true;
  }

  /** Whether the light's transform and, for a dispersive film, the row terms of each grid are at hand (each asked of its worker at once). */
  private inputsReady(s: FilmSettings, grids: readonly Grid[]): boolean {
    const ready = [spectralTransformReady(s.illuminant, s.normalization)];
    if (isDispersiveFilm(s)) ready.push(...grids.map((g) => dispersiveRowsReady(dispersiveRowsKey(s, this.rowLayout(s, g)))));
    return ready.every(Boolean);
  }

  /** The layout of the row terms of `grid` for `s`: the table's, with the grid's rows and the settings' bins. */
  private rowLayout(s: FilmSettings, grid: Grid): FilmTableLayout {
    return { ...this.quality.table, rows: grid.rows, spectralBins: spectralBinsFor(s, this.quality, this.quality.table.spectralBins) };
  }

  /**
   * `draw` in the app's frames, timed for the budget: by the GPU's timer where it has one (the
   * result comes frames later, costing no wait), else by waiting for the GPU (`syncTimed`).
   */
  private timedDraw(renderer: WebGLRenderer, s: FilmSettings, target: WebGLRenderTarget, grid: Grid, columns: Columns): void {
    const kind = passKind(s);
    const texels = (columns[1] - columns[0]) * 2 * grid.rows;
    const follows = this.drawsFollow;
    this.drawsFollow = true;
    const report = (began: number, ms: number) => {
      if (!follows) this.budget.idle();
      this.budget.drawn(kind, texels, began, ms);
    };
    this.timer ??= GpuTimer.of(renderer);
    const timer = this.timer;
    this.draw(renderer, s, target, grid, [columns], (pass) => {
      if (!timer) {
        const { began, ms } = syncTimed(renderer, target, columns[0], pass);
        return report(began, ms);
      }
      const began = performance.now();
      timer.time(pass, (ms) => report(began, ms));
    });
  }

  /** The full grid for the settings (its width follows the thickness range and the film's index). */
  private fullGrid(s: FilmSettings): Grid {
    const layout = this.quality.table;
    return { width: filmTableWidth(layout, maxFieldThicknessNm(s), filmIndexMax(s.nFilm)), rows: layout.rows };
  }

  private buildFull(renderer: WebGLRenderer, s: FilmSettings): void {
    const started = performance.now();
    this.draw(renderer, s, this.target, this.fullGrid(s), null, (pass) => syncTimed(renderer, this.target, 0, pass));
    this.lastBuildMs = performance.now() - started;
  }

  /**
   * Builds the full grid for `s` in only the columns that looking the table up at these thicknesses
   * reads (a lookup blends two neighbouring columns), and leaves the rest of the texture undefined:
   * for checks that read the table at known films, at a fraction of a full build's cost on a slow
   * GPU. Nothing counts it as built: the next `update` builds the whole table.
   */
  buildAround(renderer: WebGLRenderer, s: FilmSettings, thicknessesNm: readonly number[]): void {
    const grid = this.fullGrid(s);
    const columns = filmTableLookupColumns(this.quality.table, thicknessesNm, maxFieldThicknessNm(s), grid.width);
    this.building = null;
    this.draw(renderer, s, this.target, grid, columns, (pass) => pass());
    this.shown = { key: '', coarse: false };
    this.shownGrid = grid;
  }

  private show(key: string, coarse: boolean, grid?: Grid): void {
    this.shown = { key, coarse };
    if (!coarse) this.builds++;
    this.shownGrid = grid ?? { width: this.target.width, rows: this.quality.table.rows };
  }

  /**
   * Runs the pass over `grid` in `target` (sized to it), over the column ranges [from, to) if given
   * (the rest of the texture is kept), through `time`, which draws it and times it.
   */
  private draw(
    renderer: WebGLRenderer,
    s: FilmSettings,
    target: WebGLRenderTarget,
    grid: Grid,
    columns: readonly Columns[] | null,
    time: (pass: () => void) => void,
  ): void {
    const type = tableTexelType(renderer, this.quality.tablePrecision);
    if (target.texture.type !== type) {
      target.dispose(); // reallocated at the new type on the next render
      target.texture.type = type;
    }
    if (target.width !== grid.width || target.height !== 2 * grid.rows) target.setSize(grid.width, 2 * grid.rows);
    this.maxThicknessNm = maxFieldThicknessNm(s);
    const bins = spectralBinsFor(s, this.quality, this.quality.table.spectralBins);
    const material = this.material(s, bins);
    const u = material.uniforms;
    u.uSpectralBins!.value = spectralBinsTexture(s.illuminant, s.normalization, bins, this);
    u.uSpectralTransform!.value = spectralTransformTexture(s.illuminant, s.normalization, this);
    // A dispersive film is filled from the bins, with their terms per row (shaders/film/filmTable.glsl).
    this.updateRows(s, grid);
    u.uDispersiveRows!.value = this.rows.texture;
    u.uAirySeriesRows!.value = this.rows.texture;
    u.uPolarization!.value = enumCode('TFC_POLARIZATION', POLARIZATIONS, s.polarization);
    updateFilmMediaUniforms(u, s);
    u.uTableMaxThicknessNm!.value = this.maxThicknessNm;
    u.uFilmTableWidth!.value = grid.width;
    u.uFilmTableRows!.value = grid.rows;
    const previous = renderer.getRenderTarget();
    target.scissorTest = true;
    time(() => {
      for (const [from, to] of columns ?? [[0, grid.width]]) {
        this.texelsDrawn += (to - from) * 2 * grid.rows;
        target.scissor.set(from, 0, to - from, 2 * grid.rows);
        renderer.setRenderTarget(target); // three takes the target's scissor as it binds it
        this.fullscreen.render(renderer, material);
      }
    });
    renderer.setRenderTarget(previous);
    // The pass reads the light's textures only while it draws: let go of them until the next
    // build, unless a full table is being built band by band.
    if (!this.building) {
      releaseSpectralBinsTexture(this);
      releaseSpectralTransformTexture(this);
    }
  }

  /**
   * The per-row terms for `s` on `grid` (computed in float64 on the CPU: a dispersive film's in a
   * worker, dispersiveRowsStore.ts, or here if not at hand), unless the texture holds them already.
   */
  private updateRows(s: FilmSettings, grid: Grid): void {
    const rowsFor = `${tableKey(s)} ${grid.rows}`;
    if (rowsFor === this.rowsFor) return;
    this.rowsFor = rowsFor;
    const rowLayout = this.rowLayout(s, grid);
    const dispersive = isDispersiveFilm(s);
    if (this.rows.dispersive !== dispersive) {
      this.rows.texture.dispose();
      const texture = dispersive
        ? dispersiveRowsTexture({ ...rowLayout, rows: this.quality.table.rows })
        : airySeriesRowsTexture(this.quality.table);
      this.rows = { texture, dispersive };
    }
    const data = this.rows.texture.image.data as Float32Array;
    if (dispersive) data.set(dispersiveRowsOf(dispersiveRowsKey(s, rowLayout)));
    else airySeriesRows(s, rowLayout, data);
    this.rows.texture.needsUpdate = true;
  }

  /**
   * Compiles the table pass for `target`'s kind of target without blocking where the GPU compiles in
   * parallel (KHR_parallel_shader_compile), and meanwhile makes the light's textures for `s` on
   * this thread (the series' transform is an FFT): before a first frame, the two overlap.
   */
  async prepare(renderer: WebGLRenderer, s: FilmSettings): Promise<void> {
    const bins = spectralBinsFor(s, this.quality, this.quality.table.spectralBins);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.coarseTarget); // three picks a program by its target (no tone mapping into a texture)
    const compiled = this.fullscreen.compileAsync(renderer, this.material(s, bins));
    renderer.setRenderTarget(previous);
    spectralBinsTexture(s.illuminant, s.normalization, bins, this);
    spectralTransformTexture(s.illuminant, s.normalization, this);
    await compiled;
  }

  /**
   * Forces a rebuild on the next update, in GPU objects of its own (after a lost context). The
   * lost context's targets, quad and row texture are let go, not disposed: three still listens
   * for their disposal with the lost context's state, and would delete objects the new context
   * does not own (a WebGL warning), for instance when a coarse grid of another size resizes a target.
   */
  invalidate(): void {
    this.target = this.newTarget(2 * this.quality.table.rows);
    this.coarseTarget = this.newTarget(2);
    this.fullscreen = new FullscreenPass();
    this.rows = { texture: airySeriesRowsTexture(this.quality.table), dispersive: false };
    this.shown = { key: '', coarse: false };
    this.building = null;
    this.waiting = false;
    this.drawsFollow = false;
    this.timer = undefined; // its queries were the lost context's
    this.rowsFor = ''; // its row terms too, with the rest of the table
  }

  /** The table pass's defines for these media and bins: one program per set. */
  private passDefines(media: Pick<FilmMedia, 'nFilm' | 'nInside'>, bins: number): Record<string, number> {
    return {
      ...filmMediaDefines(media),
      TFC_POLARIZATION_UNIFORM: 1,
      ...enumConstants('TFC_POLARIZATION', POLARIZATIONS),
      ...spectralBinDefines(bins, this.quality.spectralTailTolerance),
      ...filmTableLayoutDefines(this.quality.table),
      ...airySeriesDefines(),
    };
  }

  /** What picks the table pass's program for `s`: a change of it needs another program. */
  passKey(s: FilmSettings): string {
    return JSON.stringify(this.passDefines(s, spectralBinsFor(s, this.quality, this.quality.table.spectralBins)));
  }

  /** The table pass for these media and bins: a kept one with those defines, else the least recently used (or a new one) given them. */
  private material(media: Pick<FilmMedia, 'nFilm' | 'nInside'>, bins: number): ShaderMaterial {
    const defines = this.passDefines(media, bins);
    const key = JSON.stringify(defines);
    const kept = this.passes.findIndex((p) => JSON.stringify(p.defines) === key);
    const pass = kept >= 0 ? this.passes.splice(kept, 1)[0]! : this.passes.length < KEPT_PASSES ? tablePass() : this.passes.pop()!;
    setDefines(pass, defines, 1); // the kept passes keep the programs of other sets
    this.passes.unshift(pass);
    return pass;
  }

  dispose(): void {
    this.target.dispose();
    this.coarseTarget.dispose();
    this.fullscreen.dispose();
    for (const pass of this.passes) pass.dispose();
    this.rows.texture.dispose();
    this.timer?.drop();
    releaseSpectralBinsTexture(this);
    releaseSpectralTransformTexture(this);
  }
}

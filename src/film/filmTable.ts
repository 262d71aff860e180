import type { ShaderMaterial, WebGLRenderTarget, WebGLRenderer } from 'three';
import type { PlaneCount } from '../physics/spectralWeights.ts';
import type { FilmQuality } from '../settings/filmQuality.ts';
import type { FilmOptics } from '../settings/filmSettings.ts';
import { tableKey } from './filmTableKey.ts';
import { type FilmTableGrid, bindFilmTable } from './filmTableGrid.ts';
import { FilmTablePass, tableTarget } from './filmTablePass.ts';
import type { ProgressiveTableBuild } from './progressiveTableBuild.ts';
import { filmPlanes } from '../settings/filmLight.ts';

export { tableKey };

/**
 * Makes a table's progressive build over its pass (`(pass) => new ProgressiveTableBuild(pass)`),
 * given by the owner of a table updated progressively: a table only ever built at once (the
 * material's) carries none of that code.
 */
export type ProgressiveBuilds = (pass: FilmTablePass) => ProgressiveTableBuild;

/** Nothing shown yet: a grid of one texel. */
const NO_GRID: FilmTableGrid = { width: 1, rows: 1, maxThicknessNm: 1 };

/**
 * The `table` method: the table pass (FilmTablePass) fills a float texture with the film's XYZ over
 * (thickness 0..max, cos θ_i 0..1), for light from outside and from inside, laid out as
 * `quality.table` says. It is rebuilt only when `tableKey` changes.
 *
 * A `progressive` update (the app's paced frames) that finds the settings changed draws a coarse grid in a small
 * texture of its own, and the progressive updates after it the full grid band by band
 * (ProgressiveTableBuild); the full one is shown once complete. A new light's spectral transform
 * is computed in a Web Worker: until it arrives, progressive updates keep the table shown (the previous
 * light's). Without `progressive` (tests, screenshots, the material) the full grid is built at once; a progressive
 * update needs the table made with its progressive builds (ProgressiveBuilds).
 */
export class FilmTable {
  private target!: WebGLRenderTarget;
  private coarseTarget!: WebGLRenderTarget;
  /** What is shown: the settings' tableKey ('' for nothing), whether from the coarse texture, and its grid (its colour planes: the targets'). */
  private shown = { key: '', coarse: false, grid: NO_GRID };
  /** Whether progressive updates wait for a new light's transform (the table shown is for other settings). */
  private waiting = false;
  private readonly pass: FilmTablePass;
  private readonly build: ProgressiveTableBuild | null;

  constructor(
    private readonly quality: FilmQuality,
    progressive: ProgressiveBuilds | null = null,
  ) {
    this.pass = new FilmTablePass(quality);
    this.build = progressive?.(this.pass) ?? null;
    this.newTargets(1);
  }

  /**
   * Whether the table shown is the coarse one, or another settings' while a progressive update waits for
   * the light's transform: more updates will make it the full one for the settings.
   */
  get coarse(): boolean {
    return this.shown.coarse || this.waiting;
  }

  /** Points a material that looks the table up (the `table` method) at it. */
  bind(uniforms: ShaderMaterial['uniforms']): void {
    bindFilmTable(uniforms, (this.shown.coarse ? this.coarseTarget : this.target).textures, this.shown.grid);
  }

  /**
   * Brings the table up to date with the settings over thicknesses up to `maxThicknessNm` (the
   * field's range, as the frame draws it: fields.ts's drawnField): at once, or if `progressive` by one step
   * (a coarse table for new settings, else the next band of the full one); returns whether what `bind` binds changed.
   */
  update(renderer: WebGLRenderer, s: FilmOptics, maxThicknessNm: number, progressive = false): boolean {
    const key = tableKey(s, maxThicknessNm);
    const planes = filmPlanes(s);
    const samePlanes = planes === this.target.textures.length;
    this.waiting = false;
    if (key !== this.shown.key && !samePlanes) this.makeTargets(planes);
    this.build?.poll();
    if (!progressive) {
      this.build?.stop();
      if (key === this.shown.key && !this.shown.coarse) return false;
      const grid = this.pass.fullGrid(s, maxThicknessNm);
      this.pass.draw(renderer, s, this.target, grid, null);
      this.pass.releaseLight();
      this.shown = { key, coarse: false, grid };
      return true;
    }
    if (!this.build) throw new Error('FilmTable: a progressive update of a table made without progressive builds');
    if (key !== this.shown.key) {
      // A table shown (the first is not waited for) stays until what it needs is at hand, unless it
      // has other colour planes: the material drawn now looks up the new planes.
      const coarse = this.build.begin(renderer, s, maxThicknessNm, this.coarseTarget, this.shown.key !== '' && samePlanes);
      this.waiting = coarse === null;
      if (coarse) this.shown = { key, coarse: true, grid: coarse };
      return coarse !== null;
    }
    const full = this.shown.coarse ? this.build.nextBand(renderer, this.target) : null;
    if (full) this.shown = { key, coarse: false, grid: full };
    return full !== null;
  }

  /**
   * A promise kept once what the full table for `s` over thicknesses up to `maxThicknessNm` is
   * computed from (the light's transform, a dispersive film's row terms) is at hand, computed in
   * Web Workers: an update then builds it without that work on this thread.
   */
  inputsWhenReady(s: FilmOptics, maxThicknessNm: number): Promise<void> {
    return this.pass.inputsWhenReady(s, [this.pass.fullGrid(s, maxThicknessNm)]);
  }

  /**
   * Compiles the table pass without blocking where the GPU compiles in parallel, and meanwhile
   * makes the light's textures for `s` (FilmTablePass.prepare).
   */
  prepare(renderer: WebGLRenderer, s: FilmOptics): Promise<void> {
    return this.pass.prepare(renderer, s, this.coarseTarget);
  }

  /** What picks the table pass's program for `s`: a change of it needs another program. */
  passKey(s: FilmOptics): string {
    return this.pass.passKey(s);
  }

  /**
   * Forces a rebuild on the next update, in GPU objects of its own (after a lost context). The
   * lost context's targets, quad and row texture are let go, not disposed: three still listens
   * for their disposal with the lost context's state, and would delete objects the new context
   * does not own (a WebGL warning), for instance when a coarse grid of another size resizes a target.
   */
  invalidate(): void {
    this.newTargets(this.target.textures.length as PlaneCount);
    this.pass.invalidate();
    this.build?.invalidate();
    this.shown = { key: '', coarse: false, grid: NO_GRID };
    this.waiting = false;
  }

  /** Targets of `planes` textures (what is shown is about to be replaced: its planes differ). */
  private makeTargets(planes: PlaneCount): void {
    this.target.dispose();
    this.coarseTarget.dispose();
    this.newTargets(planes);
  }

  /** New targets of `planes` textures, the old ones let go (disposed by the caller, or a lost context's). */
  private newTargets(planes: PlaneCount): void {
    this.target = tableTarget(2 * this.quality.table.rows, planes);
    this.coarseTarget = tableTarget(2, planes);
  }

  dispose(): void {
    this.target.dispose();
    this.coarseTarget.dispose();
    this.pass.dispose();
    this.build?.dispose();
  }
}

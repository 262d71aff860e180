/**
 * The `table` method for the node material: a half-float texture of the film's XYZ (or of the
 * three columns of its environment matrix, one grid above the other, filled at once) over
 * (thickness 0..max, cos θ_i 0..1) for light from outside, laid out as the quality's table says
 * (filmTableLayout.ts), filled on the GPU (filmTableFill.ts): by compute into a storage texture on
 * WebGPURenderer's WebGPU backend (filmTableCompute.ts), by a render pass into a render target on
 * its WebGL2 backend (filmTablePass.ts). Each texel is the film at the texel's thickness and angle
 * by the binned integral: the texel's own film, as the GLSL's series fill gives it; averaged over
 * the texel's thickness cell, as the GLSL's binned fill does, it measured ΔE00 1.07 on the parity
 * harness's stress grid, against 0.92. It is looked up with the GPU's filtering (half float
 * filters on every backend; a float32 texture filters only with `float32-filterable`). The twin of
 * src/film/filmTable.ts, shaders/film/filmTable.glsl and shaders/methods/tableMethod.glsl.
 */
import { Fn, texture, uniform, vec2 } from 'three/tsl';
import { type Node, type Renderer } from 'three/webgpu';
import { filmSpectralBins, fillGpu } from '../film/filmFillGpu.ts';
import { tableKey } from '../film/filmTableKey.ts';
import { releaseSpectralBinsTexture, spectralBinDefines, spectralBinsTexture } from '../film/spectralBinsTexture.ts';
import { uniformField } from '../fields/uniformField.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type PlaneCount } from '../physics/spectralWeights.ts';
import { type MaterialFilmSettings } from '../meshMaterial/materialFilm.ts';
import { filmTableLookupColumns, filmTableWidth } from '../settings/filmTableLayout.ts';
import { type FloatNode } from './complex.ts';
import { type FilmNodes, filmXyz } from './filmColor.ts';
import { floatRow } from './filmInputs.ts';
import { CHANNEL_KINDS, type Channels, channelWeights, channelsOf } from './filmReflectance.ts';
import { TableCompute } from './filmTableCompute.ts';
import { type TableFill, type TableGrid, type TexelXyz, computesOn } from './filmTableFill.ts';
import { tableCosIncidence, tableThicknessNm, tableUv } from './filmTableLayout.ts';
import { TablePass } from './filmTablePass.ts';

/**
 * The thickness of the table's last column: a material's film is the uniform field (filmSettingsOf
 * gives it the thickness range's larger end), whose largest thickness uniformField.ts says; read
 * from that field alone, so the entry loads no other field.
 */
const tableMaxThicknessNm = (s: MaterialFilmSettings): number => uniformField.maxThicknessNm(s, null);

/** The film's nodes a fill reads, bar its channels and bins (the table's own). */
export type FillFilm = Omit<FilmNodes, 'bins' | 'channels'>;

/** A fill of the table for one backend and the key of the film it holds. */
interface Filled {
  readonly fill: TableFill;
  builtKey: string;
}

export class NodeFilmTable {
  private readonly grid: TableGrid = { width: uniform(1), rows: uniform(1), maxThicknessNm: uniform(1), planes: uniform(1) };
  /** the bin weights of the table's integral (its own count: the quality's table.spectralBins for a film of constant media) */
  private readonly weights = texture(floatRow(1));
  /** the weights of s and p in the fill (channelsFor) */
  private readonly physicalWeights = CHANNEL_KINDS.unpolarized.map(() => uniform(0));
  /** by backend: compute (true) or the render pass (false); a renderer of each may draw the material */
  private readonly fills = new Map<boolean, Filled>();

  /** `planes`: the film's XYZ (1), or the three columns of its environment matrix, one grid above the other in the one texture. */
  constructor(
    readonly quality: FilmQuality,
    readonly planes: PlaneCount = 1,
  ) {
    this.grid.planes.value = planes;
  }

  /**
   * The film's colour planes at a thickness and cos θ_i: one filtered lookup per plane of the
   * texture its renderer's backend fills, texel centres at the ends of each plane's ranges
   * (docs/gpu.md#texel-centres), so no lookup reads a texel of another plane.
   */
  lookups(thicknessNm: FloatNode, cosIncidence: FloatNode): Node<'vec3'>[] {
    const { width, rows, maxThicknessNm } = this.grid;
    return Array.from({ length: this.planes }, (_, p) =>
      Fn((builder) => {
        const at = tableUv(this.quality.table, thicknessNm, cosIncidence, maxThicknessNm);
        const texel = vec2(at.x.mul(width.sub(1)).add(0.5), at.y.mul(rows.sub(1)).add(0.5).add(rows.mul(p)));
        return texture(this.filledBy(builder.renderer).fill.texture, texel.div(vec2(width, rows.mul(this.planes)))).xyz;
      })(),
    );
  }

  /** Whether the table holds the film of `s` (the key of what it depends on), on a backend that draws it. */
  holds(s: MaterialFilmSettings): boolean {
    const key = this.keyOf(s);
    return [...this.fills.values()].some((f) => f.builtKey === key);
  }

  /**
   * Fills the table for `s` with `renderer` where it holds another film; `film`: the film's nodes
   * bar its channels and bins. Where the fill builds off the frame (the render pass), a table
   * filled before keeps its film until the new fill's program is built (`prepare`), so that no
   * option change builds one on this thread.
   */
  update(renderer: Renderer, s: MaterialFilmSettings, film: FillFilm): void {
    const key = this.keyOf(s);
    const filled = this.filledBy(renderer);
    if (key === filled.builtKey) return;
    const plan = this.fillOf(s, film);
    const offFrame = filled.fill.offFrame;
    if (offFrame && filled.builtKey !== '' && !offFrame.isBuilt(plan.program)) {
      void offFrame.build(renderer, plan.program, plan.xyz);
      return;
    }
    plan.setInputs();
    filled.fill.fill(renderer, plan.program, plan.xyz, null);
    filled.builtKey = key;
  }

  /**
   * Fills, for `s`, only the columns that looking the table up at these thicknesses reads (a
   * lookup blends two neighbouring columns), the rest left undefined: those films' colours at a
   * fraction of a whole table's cost (the parity probe's); the table then holds no film.
   */
  updateAround(renderer: Renderer, s: MaterialFilmSettings, film: FillFilm, thicknessesNm: readonly number[]): void {
    const filled = this.filledBy(renderer);
    const plan = this.fillOf(s, film);
    plan.setInputs();
    const columns = filmTableLookupColumns(this.quality.table, thicknessesNm, this.grid.maxThicknessNm.value, this.grid.width.value);
    filled.fill.fill(renderer, plan.program, plan.xyz, columns);
    filled.builtKey = '';
  }

  /** Builds, off the frame, the program that fills the table for `s` where it holds another film: done when `update` fills it at once. */
  prepare(renderer: Renderer, s: MaterialFilmSettings, film: FillFilm): Promise<void> {
    const filled = this.filledBy(renderer);
    const offFrame = filled.fill.offFrame;
    if (!offFrame || this.keyOf(s) === filled.builtKey) return Promise.resolve();
    const { program, xyz } = this.fillOf(s, film);
    return offFrame.build(renderer, program, xyz);
  }

  dispose(): void {
    for (const { fill } of this.fills.values()) fill.dispose();
    releaseSpectralBinsTexture(this);
  }

  /**
   * The fill for `s`: its program's name (the same name, the same program), its texel's XYZ, and
   * what sets the inputs the program reads (the bin weights, the grid, the channels' weights) to
   * `s`'s, called just before it fills.
   */
  private fillOf(s: MaterialFilmSettings, film: FillFilm): { program: string; xyz: TexelXyz; setInputs: () => void } {
    const q = this.quality;
    const count = filmSpectralBins(s, q, q.table.spectralBins);
    const bins = spectralBinDefines(count, q.spectralTailTolerance);
    const channels = this.channelsFor(s.polarization);
    const nodes = (plane: Node<'int'>): FilmNodes => ({
      ...film,
      channels,
      bins: { count, first: bins.TFC_SPECTRAL_BIN_FIRST!, end: bins.TFC_SPECTRAL_BIN_END!, weights: this.weights, plane },
    });
    const max = this.grid.maxThicknessNm;
    const setInputs = () => {
      this.weights.value = spectralBinsTexture(s, count, this, this.planes);
      const maxThicknessNm = tableMaxThicknessNm(s);
      // The width resolves the fringes of the film (or of a stack's films that follow the thickness): FilmTablePass.fullGrid's.
      const index = fillGpu(s).fieldIndex(s, count);
      this.grid.width.value = index === null ? 2 : filmTableWidth(q.table, maxThicknessNm, index);
      this.grid.rows.value = q.table.rows;
      this.grid.maxThicknessNm.value = maxThicknessNm;
      if (s.polarization !== 'paper')
        channelWeights(s.polarization, channels.kinds).forEach((w, i) => (this.physicalWeights[i]!.value = w));
    };
    return {
      program: JSON.stringify([film.fill, channels.kinds, bins]),
      xyz: (u, v, plane) => filmXyz(nodes(plane), tableThicknessNm(q.table, u, max), tableCosIncidence(q.table, v)),
      setInputs,
    };
  }

  /**
   * The fill's channels for polarisation `p`: s and p in one program, weighted by uniforms (set
   * with the fill's inputs), so that a change among unpolarised, s and p refills the table with
   * the program it has; the paper's average of the amplitudes in its own.
   */
  private channelsFor(p: Polarization): Channels {
    return p === 'paper' ? channelsOf(p) : { kinds: CHANNEL_KINDS.unpolarized, weights: this.physicalWeights };
  }

  private keyOf(s: MaterialFilmSettings): string {
    return JSON.stringify([this.quality, tableKey(s, tableMaxThicknessNm(s))]);
  }

  /** The fill of `renderer`'s backend, made at its first use. */
  private filledBy(renderer: Renderer): Filled {
    const compute = computesOn(renderer);
    const known = this.fills.get(compute);
    if (known) return known;
    const made = { fill: compute ? new TableCompute(this.grid) : new TablePass(this.grid), builtKey: '' };
    this.fills.set(compute, made);
    return made;
  }
}

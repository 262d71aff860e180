/**
 * The `table` method for the node material: a half-float texture of the film's XYZ over
 * (thickness 0..max, cos θ_i 0..1) for light from outside, laid out as the quality's table says
 * (filmTableLayout.ts), filled on the GPU by a render pass (a quad whose fragment is the film at
 * the texel's thickness and angle by the binned integral: the texel's own film, as the GLSL's
 * series fill gives it; averaged over the texel's thickness cell, as the GLSL's binned fill does,
 * it measured ΔE00 1.07 on the parity harness's stress grid, against 0.92) and looked up with the
 * GPU's filtering (half float filters on every backend; a float32 texture filters only with
 * `float32-filterable`). The twin of src/film/filmTable.ts, shaders/film/filmTable.glsl and
 * shaders/methods/tableMethod.glsl.
 */
import { HalfFloatType, LinearFilter, RenderTarget } from 'three';
import { Fn, texture, uniform, uv, vec2, vec4 } from 'three/tsl';
import { type Node, NodeMaterial, QuadMesh, type Renderer, type UniformNode } from 'three/webgpu';
import { fillGpu, filmSpectralBins } from '../film/filmFillGpu.ts';
import { tableKey } from '../film/filmTableKey.ts';
import { releaseSpectralBinsTexture, spectralBinDefines, spectralBinsTexture } from '../film/spectralBinsTexture.ts';
import { uniformField } from '../fields/uniformField.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { type MaterialFilmSettings } from '../meshMaterial/materialFilm.ts';
import { filmTableWidth } from '../settings/filmTableLayout.ts';
import { type FloatNode } from './complex.ts';
import { type FilmNodes, filmXyz } from './filmColor.ts';
import { floatRow } from './filmInputs.ts';
import { tableCosIncidence, tableThicknessNm, tableUv } from './filmTableLayout.ts';

/** The grid the table holds: texels along thickness, rows, the thickness of its last column. */
interface Grid {
  readonly width: UniformNode<'float', number>;
  readonly rows: UniformNode<'float', number>;
  readonly maxThicknessNm: UniformNode<'float', number>;
}

/**
 * The thickness of the table's last column: a material's film is the uniform field (filmSettingsOf
 * gives it the thickness range's larger end), whose largest thickness uniformField.ts says; read
 * from that field alone, so the entry loads no other field.
 */
const tableMaxThicknessNm = (s: MaterialFilmSettings): number => uniformField.maxThicknessNm(s, null);

export class NodeFilmTable {
  private readonly target = new RenderTarget(1, 1, {
    type: HalfFloatType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
  private readonly grid: Grid = { width: uniform(1), rows: uniform(1), maxThicknessNm: uniform(1) };
  /** the bin weights of the table's integral (its own count: the quality's table.spectralBins for a film of constant media) */
  private readonly weights = texture(floatRow(1));
  private pass: { readonly key: string; readonly quad: QuadMesh; readonly material: NodeMaterial } | null = null;
  private builtKey = '';

  constructor(readonly quality: FilmQuality) {}

  /** The film's XYZ at a thickness and cos θ_i: one filtered lookup, texel centres at the ends of the ranges (docs/gpu.md#texel-centres). */
  lookup(thicknessNm: FloatNode, cosIncidence: FloatNode): Node<'vec3'> {
    const { width, rows, maxThicknessNm } = this.grid;
    const at = tableUv(this.quality.table, thicknessNm, cosIncidence, maxThicknessNm);
    const texel = vec2(at.x.mul(width.sub(1)).add(0.5), at.y.mul(rows.sub(1)).add(0.5));
    return texture(this.target.texture, texel.div(vec2(width, rows))).xyz;
  }

  /** Whether the table holds the film of `s` (the key of what it depends on). */
  holds(s: MaterialFilmSettings): boolean {
    return this.builtKey === this.keyOf(s);
  }

  /** Draws the table for `s` with `renderer` where it holds another film; `film`: the film's nodes bar the bins. */
  update(renderer: Renderer, s: MaterialFilmSettings, film: Omit<FilmNodes, 'bins'>): void {
    const key = this.keyOf(s);
    if (key === this.builtKey) return;
    const q = this.quality;
    const count = filmSpectralBins(s, q, q.table.spectralBins);
    this.weights.value = spectralBinsTexture(s, count, this);
    const maxThicknessNm = tableMaxThicknessNm(s);
    // The width resolves the fringes of the film (or of a stack's films that follow the thickness): FilmTablePass.fullGrid's.
    const index = fillGpu(s).fieldIndex(s, count);
    const width = index === null ? 2 : filmTableWidth(q.table, maxThicknessNm, index);
    this.grid.width.value = width;
    this.grid.rows.value = q.table.rows;
    this.grid.maxThicknessNm.value = maxThicknessNm;
    this.target.setSize(width, q.table.rows);
    const previous = renderer.getRenderTarget();
    renderer.setRenderTarget(this.target);
    this.passFor(count, film).render(renderer);
    renderer.setRenderTarget(previous);
    this.builtKey = key;
  }

  dispose(): void {
    this.target.dispose();
    this.pass?.material.dispose();
    releaseSpectralBinsTexture(this);
  }

  private keyOf(s: MaterialFilmSettings): string {
    return JSON.stringify([this.quality, tableKey(s, tableMaxThicknessNm(s))]);
  }

  /** The pass's quad for the film's program (its fill, channels and bins), made again when that changes. */
  private passFor(count: number, film: Omit<FilmNodes, 'bins'>): QuadMesh {
    const bins = spectralBinDefines(count, this.quality.spectralTailTolerance);
    const key = JSON.stringify([film.fill, film.kinds, bins]);
    if (this.pass?.key === key) return this.pass.quad;
    this.pass?.material.dispose();
    const nodes: FilmNodes = {
      ...film,
      bins: { count, first: bins.TFC_SPECTRAL_BIN_FIRST!, end: bins.TFC_SPECTRAL_BIN_END!, weights: this.weights },
    };
    const material = new NodeMaterial();
    material.fragmentNode = Fn(() => vec4(this.texelXyz(nodes), 1))();
    this.pass = { key, quad: new QuadMesh(material), material };
    return this.pass.quad;
  }

  /** The XYZ of the texel the pass draws: its thickness and cos θ_i from its centre (u, v run from the first to the last texel centre). */
  private texelXyz(film: FilmNodes): Node<'vec3'> {
    const { width, rows, maxThicknessNm } = this.grid;
    const layout = this.quality.table;
    const u = uv().x.mul(width).sub(0.5).div(width.sub(1));
    const v = uv().y.mul(rows).sub(0.5).div(rows.sub(1));
    return filmXyz(film, tableThicknessNm(layout, u, maxThicknessNm), tableCosIncidence(layout, v));
  }
}

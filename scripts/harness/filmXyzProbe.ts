/**
 * Renders film XYZ through the real shaders (shaders/film/filmColor.glsl, via shaderSource) into a
 * float target and reads it back: one draw per group, one pixel per case, no colour conversion.
 * In `table` mode the table is built by the app's own FilmTable pass, covering the group's
 * largest thickness (as the bubble's table covers its field's), in the columns the cases read.
 * Used by the parity harness and the benchmark's error columns.
 */
import { FULLSCREEN_VERTEX } from '../../src/gpu/fullscreenPass.ts';
import { ShaderMaterial, type WebGLRenderer } from 'three';
import { filmColorDefines, filmColorUniforms, updateFilmColorUniforms } from '../../src/film/filmColor.ts';
import { type FilmQuality } from '../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { FilmTable } from '../../src/film/filmTable.ts';
import { floatRowTexture, renderFloatRow } from '../../src/gpu/floatRow.ts';
import { shaderSource } from '../../src/gpu/shaderSource.ts';
import type { ParityGroup, ParityMode } from './parityCase.ts';

const FRAGMENT = `${shaderSource('filmColor.glsl')}
uniform sampler2D uInputs; // r: thickness in nm, g: cos θ_i
void main() {
  vec2 film = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0).rg;
  gl_FragColor = vec4(tfcFilmXyz(film.x, film.y, false), 1.0);
}`;

export class FilmXyzProbe {
  private readonly materials = new Map<string, ShaderMaterial>();
  private readonly tables = new Map<string, FilmTable>();

  constructor(private readonly renderer: WebGLRenderer) {}

  /** XYZ per case of every group, in the groups' order, as the shader computes it. */
  render(groups: readonly ParityGroup[], mode: ParityMode, quality: FilmQuality): number[][][] {
    return groups.map((g) => this.renderGroup(g, mode, quality));
  }

  private material(mode: ParityMode, g: ParityGroup, quality: FilmQuality): ShaderMaterial {
    const defines = filmColorDefines({ ...g, mode }, quality);
    const key = JSON.stringify(defines);
    const hit = this.materials.get(key);
    if (hit) return hit;
    const m = new ShaderMaterial({
      defines,
      uniforms: { uInputs: { value: null }, ...filmColorUniforms() },
      vertexShader: FULLSCREEN_VERTEX,
      fragmentShader: FRAGMENT,
    });
    this.materials.set(key, m);
    return m;
  }

  private table(quality: FilmQuality): FilmTable {
    const key = JSON.stringify(quality);
    const table = this.tables.get(key) ?? new FilmTable(quality);
    this.tables.set(key, table);
    return table;
  }

  private renderGroup(g: ParityGroup, mode: ParityMode, quality: FilmQuality): number[][] {
    const inputTexture = floatRowTexture(g.inputs.map(([thicknessNm, cosIncidence]) => [thicknessNm, cosIncidence, 0, 0]));
    const m = this.material(mode, g, quality);
    const u = m.uniforms;
    u.uInputs!.value = inputTexture;
    let table: FilmTable | null = null;
    if (mode === 'table') {
      table = this.table(quality);
      const thicknessesNm = g.inputs.map(([t]) => t);
      const settings = { ...DEFAULT_SETTINGS, ...g, field: 'uniform', thicknessNm: Math.max(...thicknessesNm), mode } as const;
      table.buildAround(this.renderer, settings, thicknessesNm);
    }
    updateFilmColorUniforms(m, { ...g, mode }, quality, table);
    const out = renderFloatRow(this.renderer, m, g.inputs.length);
    inputTexture.dispose();
    return g.inputs.map((_, i) => [out[4 * i]!, out[4 * i + 1]!, out[4 * i + 2]!]);
  }
}

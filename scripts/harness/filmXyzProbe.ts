/**
 * Renders film XYZ through the real shaders (shaders/film/filmColor.glsl, via shaderSource) into a
 * float target and reads it back: one draw per group, one pixel per case, no colour conversion.
 * In `table` mode the table is drawn by the app's own table pass (FilmTablePass), over the grid
 * covering the group's largest thickness (as the bubble's table covers its field's), in only the
 * columns the cases' lookups read. Used by the parity harness and the benchmark's error columns.
 */
import { FULLSCREEN_VERTEX } from '../../src/gpu/fullscreenPass.ts';
import { maxFieldThicknessNm } from '../../src/fields/fields.ts';
import { ShaderMaterial, Vector3, type WebGLRenderTarget, type WebGLRenderer } from 'three';
import { type FilmTableBinding, filmColorDefines, filmColorUniforms, updateFilmColorUniforms } from '../../src/film/filmColor.ts';
import { type FilmQuality } from '../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { WHITE_TINT } from '../../src/physics/lightTint.ts';
import { filmPlanes } from '../../src/settings/filmLight.ts';
import type { FilmSettings } from '../../src/settings/filmSettings.ts';
import { filmTableLookupColumns } from '../../src/settings/filmTableLayout.ts';
import { bindFilmTable, filmTablePlanesUniforms } from '../../src/film/filmTableGrid.ts';
import { filmStackUniforms } from '../../src/film/filmStack.ts';
import { FilmTablePass, tableTarget } from '../../src/film/filmTablePass.ts';
import { floatRowTexture, renderFloatRow } from '../../src/gpu/floatRow.ts';
import { shaderSource } from '../../src/gpu/shaderSource.ts';
import type { ParityGroup, ParityMode } from './parityCase.ts';
import { methodReads } from '../../src/methods/methods.ts';

const FRAGMENT = `${shaderSource('filmColor.glsl')}
uniform sampler2D uInputs; // r: thickness in nm, g: cos θ_i
uniform vec3 uReflectedColor; // with the environment matrix: the colour it reflects
void main() {
  vec2 film = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0).rg;
#ifdef TFC_ENVIRONMENT_MATRIX
  gl_FragColor = vec4(tfcReflectedXyz(tfcFilmXyz(film.x, film.y, false), uReflectedColor), 1.0);
#else
  gl_FragColor = vec4(tfcFilmXyz(film.x, film.y, false), 1.0);
#endif
}`;

/** The environment a group's film is seen in: a uniform one of the colour it reflects, if it has one (its environment matrix), else none. */
const environmentOf = (g: ParityGroup): Pick<FilmSettings, 'env'> => ({ env: g.environmentColor ? { color: g.environmentColor } : 'none' });

export class FilmXyzProbe {
  private readonly materials = new Map<string, ShaderMaterial>();
  /** A table pass and its target per quality. */
  private readonly tables = new Map<string, { readonly pass: FilmTablePass; readonly target: WebGLRenderTarget }>();

  constructor(private readonly renderer: WebGLRenderer) {}

  /** XYZ per case of every group, in the groups' order, as the shader computes it. */
  render(groups: readonly ParityGroup[], mode: ParityMode, quality: FilmQuality): number[][][] {
    return groups.map((g) => this.renderGroup(g, mode, quality));
  }

  private material(mode: ParityMode, g: ParityGroup, quality: FilmQuality): ShaderMaterial {
    const defines = filmColorDefines({ ...g, ...environmentOf(g), mode }, quality);
    const key = JSON.stringify(defines);
    const hit = this.materials.get(key);
    if (hit) return hit;
    const m = new ShaderMaterial({
      defines,
      uniforms: {
        uInputs: { value: null },
        uReflectedColor: { value: new Vector3() },
        ...filmColorUniforms(),
        ...filmTablePlanesUniforms(),
        ...filmStackUniforms(),
      },
      vertexShader: FULLSCREEN_VERTEX,
      fragmentShader: FRAGMENT,
    });
    this.materials.set(key, m);
    return m;
  }

  /**
   * The table for `s` in only the columns that looking it up at these thicknesses reads (a lookup
   * blends two neighbouring columns), the rest of its texture left undefined: the cases' colours at
   * a fraction of a full table's cost on a slow GPU.
   */
  private tableAround(quality: FilmQuality, s: FilmSettings, thicknessesNm: readonly number[]): FilmTableBinding {
    const key = JSON.stringify([quality, filmPlanes(s)]);
    const table = this.tables.get(key) ?? { pass: new FilmTablePass(quality), target: tableTarget(2 * quality.table.rows, filmPlanes(s)) };
    this.tables.set(key, table);
    const grid = table.pass.fullGrid(s, maxFieldThicknessNm(s));
    const columns = filmTableLookupColumns(quality.table, thicknessesNm, grid.maxThicknessNm, grid.width);
    table.pass.draw(this.renderer, s, table.target, grid, columns);
    table.pass.releaseLight();
    return { bind: (u) => bindFilmTable(u, table.target.textures, grid) };
  }

  private renderGroup(g: ParityGroup, mode: ParityMode, quality: FilmQuality): number[][] {
    const inputTexture = floatRowTexture(g.inputs.map(([thicknessNm, cosIncidence]) => [thicknessNm, cosIncidence, 0, 0]));
    const m = this.material(mode, g, quality);
    const u = m.uniforms;
    u.uInputs!.value = inputTexture;
    let table: FilmTableBinding | null = null;
    if (methodReads(mode, 'table')) {
      const thicknessesNm = g.inputs.map(([t]) => t);
      const settings = {
        ...DEFAULT_SETTINGS,
        ...g,
        ...environmentOf(g),
        field: 'uniform',
        thicknessNm: Math.max(...thicknessesNm),
        mode,
      } as const;
      table = this.tableAround(quality, settings, thicknessesNm);
    }
    updateFilmColorUniforms(m, { lightTint: WHITE_TINT, ...g, ...environmentOf(g), mode }, quality, table);
    // What the bubble's walls reflect through M: the room's colour (the light's white without one) times the tint.
    const tint = g.lightTint ?? WHITE_TINT;
    (u.uReflectedColor!.value as Vector3).fromArray((g.environmentColor ?? WHITE_TINT).map((c, i) => c * tint[i]!));
    const out = renderFloatRow(this.renderer, m, g.inputs.length);
    inputTexture.dispose();
    return g.inputs.map((_, i) => [out[4 * i]!, out[4 * i + 1]!, out[4 * i + 2]!]);
  }
}

import { GLSL3, ShaderMaterial } from 'three';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { enumConstants } from '../gpu/enumDefines.ts';
import { FULLSCREEN_VERTEX } from '../gpu/fullscreenPass.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { texelRecordDefines } from '../gpu/texelRecord.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { AIRY_ROW } from './airySeriesRows.ts';
import { DISPERSIVE_BIN } from './dispersiveRows.ts';
import { filmShaderSource } from './filmShaderSource.ts';
import { filmMediaDefines, filmSpectralBins, filmStackDefines } from './filmFillGpu.ts';
import { type FilmMedia, filmMediaUniforms } from './filmMedia.ts';
import { filmTableGridUniforms } from './filmTableGrid.ts';
import { type StackedSettings, filmStackUniforms } from './filmStack.ts';
import { filmTableLayoutDefines } from './filmTableDefines.ts';
import { KEPT_PASSES, TABLE_PASS_NAME } from './keptPasses.ts';
import { spectralBinDefines, spectralBinsUniforms } from './spectralBinsTexture.ts';
import { airySeriesDefines, spectralTransformUniforms } from './spectralTransformTexture.ts';

/** The media that pick the table pass's program (the outside's index is a uniform), or a stack of films, and the colour planes (filmPlanes) it writes. */
export type PassMedia = Pick<FilmMedia, 'nFilm' | 'nInside'> & StackedSettings & Partial<Pick<FilmSettings, 'env'>>;

/**
 * The uniforms shaders/film/filmTable.glsl declares: the light's textures, the per-row terms
 * (one texture, bound to the series' or the dispersive bins' sampler), the polarisation, the media
 * and the grid it draws.
 */
export const filmTablePassUniforms = (): ShaderMaterial['uniforms'] => ({
  ...spectralBinsUniforms(),
  ...spectralTransformUniforms(),
  uAirySeriesRows: { value: null },
  uDispersiveRows: { value: null },
  uPolarization: { value: 0 },
  ...filmMediaUniforms(),
  ...filmStackUniforms(),
  ...filmTableGridUniforms(),
});

/** A table pass (shaders/film/filmTable.glsl) with no defines yet. */
const tablePass = (): ShaderMaterial =>
  new ShaderMaterial({
    name: TABLE_PASS_NAME,
    uniforms: filmTablePassUniforms(),
    vertexShader: FULLSCREEN_VERTEX,
    fragmentShader: filmShaderSource('filmTable.glsl'),
    glslVersion: GLSL3, // its outputs are its own: a texel in each colour plane
  });

/**
 * The table pass's programs: a material per set of defines, the last used first, KEPT_PASSES at
 * most. Its defines follow the media and the spectral bins only: the polarisation is a uniform, so
 * changing it compiles nothing.
 */
export class TablePassPrograms {
  private readonly passes: ShaderMaterial[] = [];

  constructor(private readonly quality: FilmQuality) {}

  /** The spectral bins the pass integrates for `s`. */
  bins(s: PassMedia): number {
    return filmSpectralBins(s, this.quality, this.quality.table.spectralBins);
  }

  /** The pass's defines for these media and bins: one program per set. */
  private defines(media: PassMedia, bins: number): Record<string, number> {
    return {
      ...filmMediaDefines(media),
      ...filmStackDefines(media),
      ...(filmPlanes(media) === 3 && { TFC_ENVIRONMENT_MATRIX: 1 }),
      TFC_POLARIZATION_UNIFORM: 1,
      ...enumConstants('TFC_POLARIZATION', POLARIZATIONS),
      ...spectralBinDefines(bins, this.quality.spectralTailTolerance),
      ...filmTableLayoutDefines(this.quality.table),
      ...texelRecordDefines(AIRY_ROW),
      ...texelRecordDefines(DISPERSIVE_BIN),
      ...airySeriesDefines(),
    };
  }

  /** What picks the pass's program for `s`: a change of it needs another program. */
  key(s: PassMedia): string {
    return JSON.stringify(this.defines(s, this.bins(s)));
  }

  /** The pass for `s`: a kept one with its defines, else the least recently used (or a new one) given them. */
  material(s: PassMedia): ShaderMaterial {
    const defines = this.defines(s, this.bins(s));
    const key = JSON.stringify(defines);
    const kept = this.passes.findIndex((p) => JSON.stringify(p.defines) === key);
    const pass = kept >= 0 ? this.passes.splice(kept, 1)[0]! : this.passes.length < KEPT_PASSES ? tablePass() : this.passes.pop()!;
    setDefines(pass, defines, 1); // the kept passes keep the programs of other sets
    this.passes.unshift(pass);
    return pass;
  }

  dispose(): void {
    for (const pass of this.passes) pass.dispose();
  }
}

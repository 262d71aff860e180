import { Matrix3, ShaderMaterial, type Texture } from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import {
  type Matrix3 as Rows3,
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
} from '../physics/colorConversions.ts';
import { EXACT_SPECTRAL_BINS, FIELDS, type FilmSettings, TABLE_ROWS, TABLE_WIDTH } from './filmSettings.ts';
import { shaderSource } from './shaderSource.ts';
import { spectralBinsTexture } from './spectralBinsTexture.ts';

const matrix3 = (rows: Rows3) => new Matrix3().set(...rows);

/** The defines shaders/filmColor.glsl needs: the method and polarisation in use, and their sizes. */
export function filmColorDefines(s: Pick<FilmSettings, 'mode' | 'polarization'>): Record<string, number> {
  return {
    FILM_MODE: s.mode === 'exact' ? 0 : 1,
    POLARIZATION: POLARIZATIONS.indexOf(s.polarization),
    SPECTRAL_BINS: EXACT_SPECTRAL_BINS,
    FILM_TABLE_WIDTH: TABLE_WIDTH,
    FILM_TABLE_ROWS: TABLE_ROWS,
  };
}

/** The compile-time switches: a shader holds only the mode, field, sides and options in use. */
export function bubbleDefines(s: FilmSettings): Record<string, number> {
  return {
    ...filmColorDefines(s),
    THICKNESS_FIELD: FIELDS.indexOf(s.field),
    SIDES: s.sides === 'both' ? 2 : 1,
    ENVIRONMENT: s.env === 'sky' ? 1 : 0,
    HATCH_OUT_OF_GAMUT: s.space === 'wide-gamut' ? 1 : 0,
  };
}

/** The bubble's ShaderMaterial (shaders/bubble.*.glsl). `updateBubbleUniforms` keeps it current. */
export function createBubbleMaterial(s: FilmSettings): ShaderMaterial {
  return new ShaderMaterial({
    defines: bubbleDefines(s),
    uniforms: {
      uSpectralBins: { value: null },
      uFilmTable: { value: null },
      uTableMaxThicknessNm: { value: 1 },
      uNOutside: { value: 1 },
      uNFilm: { value: 1.33 },
      uNInside: { value: 1 },
      uThicknessNm: { value: 500 },
      uThicknessRangeNm: { value: 0 },
      uSwirlSpeed: { value: 0 },
      uTimeSeconds: { value: 0 },
      uExposure: { value: 1 },
      uXyzToLinearWorking: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
      uXyzToLinearDisplay: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
    },
    vertexShader: shaderSource('bubble.vert.glsl'),
    fragmentShader: shaderSource('bubble.frag.glsl'),
  });
}

export function updateBubbleUniforms(
  m: ShaderMaterial,
  s: FilmSettings,
  table: { texture: Texture; maxThicknessNm: number } | null,
  displayIsP3: boolean,
): void {
  const u = m.uniforms;
  const defines = bubbleDefines(s);
  if (JSON.stringify(defines) !== JSON.stringify(m.defines)) {
    m.dispose(); // frees the old program (three keeps one per define set until the material is disposed)
    m.defines = defines;
    m.needsUpdate = true;
  }
  u.uSpectralBins!.value = spectralBinsTexture(s.illuminant, s.normalization, EXACT_SPECTRAL_BINS);
  u.uFilmTable!.value = table?.texture ?? null;
  u.uTableMaxThicknessNm!.value = table?.maxThicknessNm ?? 1;
  u.uNOutside!.value = s.nOutside;
  u.uNFilm!.value = s.nFilm;
  u.uNInside!.value = s.nInside;
  u.uThicknessNm!.value = s.thicknessNm;
  u.uThicknessRangeNm!.value = s.thicknessRangeNm;
  u.uSwirlSpeed!.value = s.swirlSpeed;
  u.uTimeSeconds!.value = s.timeSeconds;
  u.uExposure!.value = s.exposure;
  (u.uXyzToLinearDisplay!.value as Matrix3).set(...(displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB));
}

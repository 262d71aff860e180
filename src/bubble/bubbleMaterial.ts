import { type DataTexture, Matrix3, ShaderMaterial } from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { type Matrix3 as Rows3, XYZ_TO_LINEAR_DISPLAY_P3, XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type FilmQuality, spectralBinsFor } from '../settings/filmQuality.ts';
import { FIELDS, FILM_METHODS, type FilmSettings } from '../settings/filmSettings.ts';
import { environmentDefines, environmentUniforms, updateEnvironmentUniforms } from './environmentMaterial.ts';
import { filmIndexDefines, filmIndexUniforms, updateFilmIndexUniforms } from '../film/filmIndexUniforms.ts';
import { filmTableLayoutDefines } from '../settings/filmTableLayout.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { airySeriesDefines, releaseSpectralTransformTexture, spectralTransformTexture } from '../film/spectralTransformTexture.ts';
import { releaseSpectralBinsTexture, spectralBinDefines, spectralBinsTexture } from '../film/spectralBinsTexture.ts';

const matrix3 = (rows: Rows3) => new Matrix3().set(...rows);

export type FilmColorSettings = Pick<FilmSettings, 'mode' | 'polarization' | 'nFilm'>;

/**
 * The defines shaders/film/filmColor.glsl needs: the method and polarisation in use, and only the
 * sizes of that method (the spectral bins it visits, or the table's layout).
 */
export function filmColorDefines(s: FilmColorSettings, q: FilmQuality): Record<string, number> {
  const method = { TFC_FILM_MODE: FILM_METHODS.indexOf(s.mode), TFC_POLARIZATION: POLARIZATIONS.indexOf(s.polarization) };
  if (s.mode === 'exact')
    return {
      ...method,
      ...spectralBinDefines(spectralBinsFor(s.nFilm, q, q.exactSpectralBins), q.spectralTailTolerance),
      ...filmIndexDefines(s.nFilm),
    };
  // The lookup does not depend on the polarisation (the table pass does), so changing it compiles no bubble.
  if (s.mode === 'table') return { TFC_FILM_MODE: method.TFC_FILM_MODE, ...filmTableLayoutDefines(q.table) };
  // The series, and the binned integral for evanescent films (which have no real optical path).
  if (s.mode === 'fourier')
    return {
      ...method,
      ...airySeriesDefines(q.airySeriesMaxOrders),
      ...spectralBinDefines(spectralBinsFor(s.nFilm, q, q.exactSpectralBins), q.spectralTailTolerance),
      ...filmIndexDefines(s.nFilm),
    };
  return method;
}

/**
 * Points a film-colour material (or any holder of its uniforms: the spectral iridescence) at the
 * light's textures its method reads (the bin weights, the spectral transform), held for it, and
 * lets go of those it does not read.
 */
export function updateFilmColorTextures(
  m: Pick<ShaderMaterial, 'uniforms'>,
  s: FilmColorSettings & Pick<FilmSettings, 'illuminant' | 'normalization'>,
  q: FilmQuality,
): void {
  const u = m.uniforms;
  const binned = s.mode === 'exact' || s.mode === 'fourier';
  if (binned)
    u.uSpectralBins!.value = spectralBinsTexture(s.illuminant, s.normalization, spectralBinsFor(s.nFilm, q, q.exactSpectralBins), m);
  else {
    releaseSpectralBinsTexture(m);
    u.uSpectralBins!.value = null;
  }
  if (s.mode === 'fourier') u.uSpectralTransform!.value = spectralTransformTexture(s.illuminant, s.normalization, m);
  else {
    releaseSpectralTransformTexture(m);
    u.uSpectralTransform!.value = null;
  }
}

/** Frees what a film-colour material holds (call before disposing it). */
export function releaseFilmColorTextures(m: object): void {
  releaseSpectralBinsTexture(m);
  releaseSpectralTransformTexture(m);
}

/** The compile-time switches: a shader holds only the mode, field, sides and options in use. */
export function bubbleDefines(s: FilmSettings, q: FilmQuality): Record<string, number> {
  return {
    ...filmColorDefines(s, q),
    TFC_THICKNESS_FIELD: FIELDS.indexOf(s.field),
    TFC_SIDES: s.sides === 'both' ? 2 : 1,
    ...environmentDefines(s),
    TFC_HATCH_OUT_OF_GAMUT: s.space === 'wide-gamut' ? 1 : 0,
  };
}

/**
 * The uniforms shaders/film/filmColor.glsl reads in any mode (the light's textures, the table and its
 * grid, the three indices), and the XYZ → working space matrix (eq 19) its users apply.
 */
export const filmColorUniforms = (): ShaderMaterial['uniforms'] => ({
  uSpectralBins: { value: null },
  uSpectralTransform: { value: null },
  uFilmTable: { value: null },
  uTableMaxThicknessNm: { value: 1 },
  uFilmTableWidth: { value: 1 },
  uFilmTableRows: { value: 1 },
  uNOutside: { value: 1 },
  ...filmIndexUniforms(),
  uNInside: { value: 1 },
  uXyzToLinearWorking: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
});

/** The bubble's ShaderMaterial (shaders/bubble/bubble.*.glsl). `updateBubbleUniforms` keeps it current. */
export function createBubbleMaterial(s: FilmSettings, q: FilmQuality): ShaderMaterial {
  return new ShaderMaterial({
    defines: bubbleDefines(s, q),
    uniforms: {
      ...filmColorUniforms(),
      uThicknessNm: { value: 500 },
      uThicknessRangeNm: { value: 0 },
      uSwirlSpeed: { value: 0 },
      uTimeSeconds: { value: 0 },
      ...environmentUniforms(),
      uXyzToLinearDisplay: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
    },
    vertexShader: shaderSource('bubble.vert.glsl'),
    fragmentShader: shaderSource('bubble.frag.glsl'),
  });
}

/**
 * Brings the material up to `s`: `table` for the table mode, `environmentMap` the texture of an
 * HDR `s.env` (the caller shows `sky` until it has arrived).
 */
export function updateBubbleUniforms(
  m: ShaderMaterial,
  s: FilmSettings,
  q: FilmQuality,
  table: { bind(uniforms: ShaderMaterial['uniforms']): void } | null,
  displayIsP3: boolean,
  environmentMap: DataTexture | null,
): void {
  const u = m.uniforms;
  setDefines(m, bubbleDefines(s, q));
  updateFilmColorTextures(m, s, q);
  if (table) table.bind(u);
  else u.uFilmTable!.value = null;
  u.uNOutside!.value = s.nOutside;
  updateFilmIndexUniforms(u, s.nFilm);
  u.uNInside!.value = s.nInside;
  u.uThicknessNm!.value = s.thicknessNm;
  u.uThicknessRangeNm!.value = s.thicknessRangeNm;
  u.uSwirlSpeed!.value = s.swirlSpeed;
  u.uTimeSeconds!.value = s.timeSeconds;
  updateEnvironmentUniforms(m, s, environmentMap);
  (u.uXyzToLinearDisplay!.value as Matrix3).set(...(displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB));
}

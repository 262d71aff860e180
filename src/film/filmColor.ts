import { Matrix3, type ShaderMaterial } from 'three';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { type Matrix3 as Rows3, XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import type { FilmOptics, FilmSettings } from '../settings/filmSettings.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import type { FilmMethodInput } from '../methods/filmMethod.ts';
import { FILM_METHOD_REGISTRY, FILM_METHODS, methodReads } from '../methods/methods.ts';
import { withOptionFilms } from '../methods/filmStacks.ts';
import { enumDefines } from '../gpu/enumDefines.ts';
import { type FilmMedia, filmMediaUniforms, opaqueInsideDefines } from './filmMedia.ts';
import { filmMediaDefines, filmSpectralBins, filmStackDefines, updateFilmMediaUniforms, updateFilmStackUniforms } from './filmFillGpu.ts';
import { filmTableLayoutDefines } from './filmTableDefines.ts';
import {
  airySeriesDefines,
  releaseSpectralTransformTexture,
  spectralTransformTexture,
  spectralTransformUniforms,
} from './spectralTransformTexture.ts';
import { bindSpectralBins, releaseSpectralBinsTexture, spectralBinDefines, spectralBinsUniforms } from './spectralBinsTexture.ts';
import { filmTableUniforms } from './filmTableGrid.ts';
import { type StackedSettings, releaseFilmStackTexture } from './filmStack.ts';

/**
 * The film's colour as shaders/film/filmColor.glsl computes it, from the TypeScript side: its
 * defines, its uniforms and one function that brings them up to the settings, shared by every
 * shader that computes a film colour (the bubble, the material for any mesh, the parity probe).
 */

export const matrix3 = (rows: Rows3) => new Matrix3().set(...rows);

export type FilmColorSettings = Pick<FilmSettings, 'mode' | 'polarization' | 'nFilm' | 'nInside'> &
  Partial<Pick<FilmSettings, 'env'>> &
  Pick<FilmOptics, 'sceneEnvironment'> &
  StackedSettings;

/** The defines each input of a method (src/methods/filmMethod.ts) brings, sized by the quality. */
const INPUT_DEFINES: Readonly<Record<FilmMethodInput, (s: FilmColorSettings, q: FilmQuality) => Record<string, number>>> = {
  polarization: (s) => enumDefines('TFC_POLARIZATION', POLARIZATIONS, s.polarization),
  media: (s) => filmMediaDefines(s),
  spectralBins: (s, q) => spectralBinDefines(filmSpectralBins(s, q, q.exactSpectralBins), q.spectralTailTolerance),
  spectralTransform: (_, q) => airySeriesDefines(q.airySeriesMaxOrders),
  table: (_, q) => filmTableLayoutDefines(q.table),
  stack: (s) => filmStackDefines(s),
};

/**
 * The defines shaders/film/filmColor.glsl needs: the method in use, and only what that method
 * reads (its registry entry says which), so a change of anything else compiles nothing.
 */
export function filmColorDefines(s: FilmColorSettings, q: FilmQuality): Record<string, number> {
  const inputs = FILM_METHOD_REGISTRY[s.mode].reads.map((input: FilmMethodInput) => INPUT_DEFINES[input](s, q));
  const planes = filmPlanes(s) === 3 ? { TFC_ENVIRONMENT_MATRIX: 1 } : {};
  return Object.assign({}, enumDefines('TFC_FILM_MODE', FILM_METHODS, s.mode), opaqueInsideDefines(s), planes, ...inputs) as Record<
    string,
    number
  >;
}

/**
 * Points a film-colour material (or any holder of its uniforms: the spectral iridescence) at the
 * light's textures its method reads (the bin weights, the spectral transform), held for it, and
 * lets go of those it does not read.
 */
function updateFilmColorTextures(
  m: Pick<ShaderMaterial, 'uniforms'>,
  s: FilmColorSettings & Pick<FilmSettings, 'illuminant' | 'lightTint' | 'normalization'>,
  q: FilmQuality,
): void {
  const u = m.uniforms;
  const bins = filmSpectralBins(s, q, q.exactSpectralBins);
  const planes = filmPlanes(s);
  if (methodReads(s.mode, 'spectralBins')) bindSpectralBins(u, s, bins, m, planes);
  else {
    releaseSpectralBinsTexture(m);
    u.uSpectralBins!.value = null;
  }
  if (methodReads(s.mode, 'spectralTransform')) u.uSpectralTransform!.value = spectralTransformTexture(s, m, planes);
  else {
    releaseSpectralTransformTexture(m);
    u.uSpectralTransform!.value = null;
  }
  // The stack's uniforms are a material's that may draw one (filmStackUniforms: the bubble, the parity probe).
  if ('uFilmLayers' in u) updateFilmStackUniforms(u, methodReads(s.mode, 'stack') ? s : withOptionFilms(s, []), bins, m);
}

/** Frees what a film-colour material holds (call before disposing it). */
export function releaseFilmColorTextures(m: object): void {
  releaseSpectralBinsTexture(m);
  releaseSpectralTransformTexture(m);
  releaseFilmStackTexture(m);
}

/**
 * The uniforms shaders/film/filmColor.glsl reads in any mode (the light's textures, the table and its
 * grid, the three media), and the XYZ → working space matrix (eq 19) its users apply.
 */
export const filmColorUniforms = (): ShaderMaterial['uniforms'] => ({
  ...spectralBinsUniforms(),
  ...spectralTransformUniforms(),
  ...filmTableUniforms(),
  ...filmMediaUniforms(),
  // shaders/film/filmWorkingSpace.glsl
  uXyzToLinearWorking: { value: matrix3(XYZ_TO_LINEAR_SRGB) },
});

/** Something that binds a film table's texture and grid (FilmTable). */
export interface FilmTableBinding {
  bind(uniforms: ShaderMaterial['uniforms']): void;
}

/**
 * Brings a film-colour material's uniforms (or any holder of filmColorUniforms) up to `s`: the
 * light's textures its method reads, the table (`null`: none bound), the three media.
 */
export function updateFilmColorUniforms(
  m: Pick<ShaderMaterial, 'uniforms'>,
  s: FilmColorSettings & FilmMedia & Pick<FilmSettings, 'illuminant' | 'lightTint' | 'normalization'>,
  q: FilmQuality,
  table: FilmTableBinding | null,
): void {
  updateFilmColorTextures(m, s, q);
  if (table) table.bind(m.uniforms);
  else m.uniforms.uFilmTable!.value = null;
  updateFilmMediaUniforms(m.uniforms, s);
}

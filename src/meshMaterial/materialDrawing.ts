/**
 * What draws a spectral material's film, loaded apart from the entry (spectralDrawing.ts) the
 * first time a material is made spectral: the film's shader written into three's, its program
 * key, its table and the light's textures, and the data they are computed from (the CIE tables).
 */
import { type MeshPhysicalMaterial, type Scene, type WebGLProgramParametersWithUniforms, type WebGLRenderer } from 'three';
import { filmColorUniforms, releaseFilmColorTextures, updateFilmColorUniforms } from '../film/filmColor.ts';
import { filmStackUniforms } from '../film/filmStack.ts';
import { spectralTransformWhenReady } from '../film/spectralTransformTexture.ts';
import { FilmTable, tableKey } from '../film/filmTable.ts';
import { uniformField } from '../fields/uniformField.ts';
import { methodReads } from '../methods/methods.ts';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import { type FilmQuality } from '../settings/filmQuality.ts';
import { restoresOf } from './contextRestores.ts';
import {
  type MaterialFilmSettings,
  drawnFilmSettings,
  filmDefinesOf,
  filmKeyOf,
  followEnvironment,
  followMetal,
  metalOf,
} from './materialFilm.ts';
import { filmTablePlanesUniforms } from '../film/filmTableGrid.ts';
import { lightTintUniforms, setLightTintUniform } from '../film/filmLightTint.ts';
import { spectralFragmentShader } from './spectralFragmentShader.ts';
import { type SpectralFilm, warnOnce } from './spectralFilm.ts';

export { filmKeyOf };

/** Film tables shared by the materials whose film, light and thickness range are the same. */
const tables = new SharedTextures((key) => new FilmTable((JSON.parse(key) as { quality: FilmQuality }).quality));
/** The context restore each table was last drawn after (contextRestores.ts): a restore empties it. */
const tableRestores = new WeakMap<FilmTable, number>();

/**
 * The film with its uniforms (filmColor.glsl's, the stack's, and in a scene with an environment the
 * table's other planes and the light's tint), made once per material. The film itself holds the
 * light's textures (filmColor.ts's holder), so that its release lets them go.
 */
const withUniforms = (film: SpectralFilm): SpectralFilm & { uniforms: NonNullable<SpectralFilm['uniforms']> } => {
  film.uniforms ??= { ...filmColorUniforms(), ...filmStackUniforms(), ...filmTablePlanesUniforms(), ...lightTintUniforms() };
  return film as SpectralFilm & { uniforms: NonNullable<SpectralFilm['uniforms']> };
};

/**
 * The table the film `s` is drawn from, held for `film` (shared with the materials of the same
 * film and light), and the thickness it reaches; null, the film's share let go, where its method reads none.
 */
function holdTable(film: SpectralFilm, s: MaterialFilmSettings): { table: FilmTable; maxThicknessNm: number } | null {
  if (!methodReads(s.mode, 'table')) {
    if (film.table) tables.release(film);
    return (film.table = null);
  }
  // The film is the same over the surface: three's thickness (its map scales it).
  const maxThicknessNm = uniformField.maxThicknessNm({ thicknessNm: s.thicknessNm }, null);
  film.table = tables.hold(JSON.stringify({ quality: film.options.quality, table: tableKey(s, maxThicknessNm) }), film);
  return { table: film.table, maxThicknessNm };
}

/**
 * Brings the film's uniforms, light textures and table (built with `renderer` if it changed, or
 * if the renderer's context was restored since) up to the material. Called inside three's render.
 */
function update(film: SpectralFilm, m: MeshPhysicalMaterial, renderer: WebGLRenderer): void {
  const o = film.options;
  const s = drawnFilmSettings(m, film);
  const held = holdTable(film, s);
  if (held) {
    const restores = restoresOf(renderer);
    if (tableRestores.get(held.table) !== restores) held.table.invalidate();
    tableRestores.set(held.table, restores);
    held.table.update(renderer, s, held.maxThicknessNm);
  }
  const holder = withUniforms(film);
  updateFilmColorUniforms(holder, s, o.quality, film.table);
  setLightTintUniform(holder.uniforms, s.lightTint);
}

/**
 * A promise kept once what the film's next draw computes its table and the light's textures from
 * (the light's spectral transform, a dispersive film's row terms) is at hand, computed in Web
 * Workers: the draw then builds the table on the GPU and uploads the textures, with no long task
 * on this thread. Asked when the drawing arrives and by whenSpectralReady.
 */
export async function prepareFilm(m: MeshPhysicalMaterial, film: SpectralFilm): Promise<void> {
  if (!(m.iridescence > 0)) return;
  const s = drawnFilmSettings(m, film);
  const held = holdTable(film, s);
  if (held) await held.table.inputsWhenReady(s, held.maxThicknessNm);
  if (methodReads(s.mode, 'spectralTransform')) await spectralTransformWhenReady(s);
}

/**
 * The film written into three's shader (onBeforeCompile), or where it cannot be (a user's edit or
 * a three.js release took a line it needs) three's film left, with a warning, rather than a throw inside render.
 */
export function compileFilm(m: MeshPhysicalMaterial, film: SpectralFilm, shader: WebGLProgramParametersWithUniforms): void {
  const fragment = spectralFragmentShader(shader.fragmentShader, metalOf(m, film.options) !== null);
  if (typeof fragment !== 'string') return warnOnce(film, fragment.missing, `no ${fragment.missing}; three's film is drawn`);
  shader.defines = { ...shader.defines, ...filmDefinesOf(m, film.options) };
  Object.assign(shader.uniforms, withUniforms(film).uniforms);
  shader.fragmentShader = fragment;
}

/**
 * Brings the film up to date before three draws `m` in `scene` (onBeforeRender): everything the
 * film needs is built before the draw, so the frame shows the settled film.
 */
export function drawFilm(m: MeshPhysicalMaterial, film: SpectralFilm, renderer: WebGLRenderer, scene: Scene): void {
  followMetal(m, film);
  followEnvironment(m, film, m.envMap ?? scene.environment);
  if (m.iridescence > 0) update(film, m, renderer);
}

/** Lets go of what the film holds: its light's textures and its share of a table. */
export function releaseFilm(film: SpectralFilm): void {
  releaseFilmColorTextures(film);
  tables.release(film);
  film.table = null;
}

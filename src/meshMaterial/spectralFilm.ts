import { type Material, type MeshPhysicalMaterial } from 'three';
import { type filmColorUniforms } from '../film/filmColor.ts';
import { type filmStackUniforms } from '../film/filmStack.ts';
import { type FilmTable } from '../film/filmTable.ts';
import {
  type CheckedOptions,
  OPTION_NAMES,
  type SpectralIridescenceOptions,
  type SpectralIridescenceProperties,
  spectralIridescenceOptions,
} from './spectralIridescenceOptions.ts';

/** What a material upgraded by `spectralIridescence` holds: its options, its uniforms, its table, its warnings. */
export interface SpectralFilm {
  options: CheckedOptions;
  /** made by the drawing (materialDrawing.ts) when the program is first compiled with the film */
  uniforms: (ReturnType<typeof filmColorUniforms> & ReturnType<typeof filmStackUniforms>) | null;
  table: FilmTable | null;
  /** the causes already warned about (once each) */
  readonly warned: Set<string>;
  /** metalStateOf at the last draw: a change three cannot see (metalness, the base colour) may need a new program */
  drawnMetal: string | null;
  /**
   * Whether the film is drawn in a scene with an environment (three's scene.environment, or the
   * material's envMap or envNode), whose light it reflects through its environment matrix: noted
   * at each draw by the WebGL entry, at each program build by the WebGPU entry
   */
  sceneEnvironment: boolean;
  /** The film's part of the program key, given by the entry's drawing once it is loaded (before, the program holds three's film). */
  programKey?: (m: MeshPhysicalMaterial, o: CheckedOptions) => string;
  /**
   * Where the entry builds a changed program off the frame (the WebGPU entry): called once the
   * film holds its new options; true where it builds the program and moves the version once it is
   * built, false where the version is to move now (three then builds it at the next draw).
   */
  programAhead?: (m: MeshPhysicalMaterial) => boolean;
}

/** A film record with `options`, before its entry's drawing gives it uniforms, a table and a program key. */
export const newFilm = (options: CheckedOptions): SpectralFilm => ({
  options,
  uniforms: null,
  table: null,
  warned: new Set(),
  drawnMetal: null,
  sceneEnvironment: false,
});

const films = new WeakMap<Material, SpectralFilm>();

/** The film of a spectral material (undefined for any other). */
export const filmOf = (m: Material): SpectralFilm | undefined => films.get(m);

/** Makes `m` a spectral material holding `film`. */
export const addFilm = (m: MeshPhysicalMaterial, film: SpectralFilm): void => void films.set(m, film);

/** Whether `material` has been upgraded by `spectralIridescence` (a ThinFilmMaterial always is). */
export const isSpectralIridescence = (material: Material): material is MeshPhysicalMaterial & SpectralIridescenceProperties =>
  films.has(material);

/** One console warning per film and cause (a frame loop would repeat it every frame). */
export function warnOnce(film: SpectralFilm, cause: string, message: string): void {
  if (film.warned.has(cause)) return;
  film.warned.add(cause);
  console.warn(`spectralIridescence: ${message}`);
}

/**
 * Gives the film new options. Where the program's defines differ, the material's `version` moves
 * (`needsUpdate`), as three's own materials do when a property changes their program: three then
 * compiles or reuses the program for the new defines and keeps the others the material was drawn
 * with until its `dispose()`. The material is never disposed here: that would tell its `dispose`
 * listeners it is gone while it is still in use.
 */
export function setOptions(m: MeshPhysicalMaterial, film: SpectralFilm, options: CheckedOptions): void {
  // Before the entry's drawing is loaded, the program holds three's film: the drawing's arrival moves the version anyway.
  const keyOf = film.programKey;
  const programChanges = keyOf !== undefined && keyOf(m, film.options) !== keyOf(m, options);
  film.options = options;
  if (programChanges && !film.programAhead?.(m)) m.needsUpdate = true;
}

/** An option of a spectral material. */
export const spectralOption = <K extends keyof CheckedOptions>(m: MeshPhysicalMaterial, name: K): CheckedOptions[K] =>
  films.get(m)!.options[name];

/** Sets one option of a spectral material, checked as `spectralIridescence` checks it (a ParameterError names it; the option keeps its value). */
export function setSpectralOption(m: MeshPhysicalMaterial, name: keyof SpectralIridescenceOptions, value: unknown): void {
  const film = films.get(m)!;
  setOptions(m, film, spectralIridescenceOptions({ ...film.options, [name]: value }));
}

/** Gives `target` the film options of `source` when both are spectral (a material's copy). */
export function copySpectralFilm(target: MeshPhysicalMaterial, source: Material): void {
  const from = films.get(source);
  const to = films.get(target);
  if (from && to) setOptions(target, to, from.options);
}

/**
 * The options as properties (SpectralIridescenceProperties), one accessor pair per name of
 * OPTION_NAMES, on `target`: ThinFilmMaterial's prototype, or an upgraded material itself. Not
 * enumerable: WebGPURenderer keys a node material's programs by its enumerable properties' values
 * too, where the film's program key (customProgramCacheKey) already names what the program holds;
 * a light changed in `table` would otherwise give the same program a new key, built again in one
 * piece for the next object that draws the material.
 */
export function defineOptionProperties(target: object): void {
  for (const name of OPTION_NAMES)
    Object.defineProperty(target, name, {
      configurable: true,
      enumerable: false,
      get(this: MeshPhysicalMaterial) {
        return spectralOption(this, name);
      },
      set(this: MeshPhysicalMaterial, value: unknown) {
        setSpectralOption(this, name, value);
      },
    });
}

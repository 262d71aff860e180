import type { FilmSettings } from '../settings/filmSettings.ts';
import { filmIndexUniforms, updateFilmIndexUniforms } from './filmIndexUniforms.ts';

/** The three media of the film: outside (a), the film (b), inside (c). */
export type FilmMedia = Pick<FilmSettings, 'nOutside' | 'nFilm' | 'nInside'>;

/**
 * The media's uniforms, declared once in GLSL by shaders/film/filmMedia.glsl (and the film's
 * knots by filmIndex.glsl): every film-colour shader (the bubble, the table pass, the material,
 * the parity probe) takes them from here.
 */
export const filmMediaUniforms = () => ({
  uNOutside: { value: 1 },
  ...filmIndexUniforms(),
  uNInside: { value: 1 },
});

/** Sets the media's uniforms to `s`. */
export function updateFilmMediaUniforms(u: Record<string, { value: unknown }>, s: FilmMedia): void {
  u.uNOutside!.value = s.nOutside;
  updateFilmIndexUniforms(u, s.nFilm);
  u.uNInside!.value = s.nInside;
}

import type { LightTint } from '../../src/physics/lightTint.ts';
import type { FilmLayer } from '../../src/physics/stackFilms.ts';
import type { FilmSettings } from '../../src/settings/filmSettings.ts';

/**
 * What the parity harness and its spec share. A group holds the cases that differ only in
 * per-pixel inputs (thickness, cos θ_i); everything else is a uniform or a define of the shader.
 */
export interface ParityGroup extends Pick<
  FilmSettings,
  'nOutside' | 'nFilm' | 'nInside' | 'illuminant' | 'polarization' | 'normalization'
> {
  /** The light's tint (none: untinted). */
  readonly lightTint?: LightTint;
  /**
   * A colour (linear sRGB relative to the light's white) the film reflects, as a uniform environment
   * of that colour: the shader computes the film's environment matrix M and renders M · colour (none:
   * the film's XYZ under the light).
   */
  readonly environmentColor?: readonly [number, number, number];
  /** A stack of films in place of nFilm (none or empty: the single film); its `d` layers take each case's thickness. */
  readonly layers?: readonly FilmLayer[];
  /** [thicknessNm, cosIncidence] per case */
  readonly inputs: readonly (readonly [number, number])[];
}

export type ParityMode = FilmSettings['mode'];

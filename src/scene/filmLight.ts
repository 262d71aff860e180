import { methodReads } from '../methods/methods.ts';
import { spectralTransformReady } from '../film/spectralTransformTexture.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';

type Light = Pick<FilmSettings, 'illuminant' | 'normalization'>;

/**
 * The light a view draws its film in: the settings' own, except for a method that reads the
 * light's spectral transform, which a worker computes: until a new light's transform arrives,
 * frames keep the light shown (`waiting`).
 */
export class FilmLight {
  private shown: Light | null = null;
  /** Whether the light drawn is the one shown before, while the new one's transform is computed. */
  waiting = false;

  /** The light to draw `s`'s film in. */
  of(s: Pick<FilmSettings, 'mode'> & Light): Light {
    const wanted = { illuminant: s.illuminant, normalization: s.normalization };
    const shown = this.shown;
    this.waiting =
      methodReads(s.mode, 'spectralTransform') &&
      shown !== null &&
      JSON.stringify(wanted) !== JSON.stringify(shown) &&
      !spectralTransformReady(s.illuminant, s.normalization);
    if (this.waiting) return shown!;
    this.shown = wanted;
    return wanted;
  }

  /** Whether the transform of `s`'s light has arrived, so a waiting view can take it. */
  arrived(s: Light): boolean {
    return spectralTransformReady(s.illuminant, s.normalization);
  }

  /** Forgets the light shown, so the next `of` takes the settings' own. */
  forget(): void {
    this.shown = null;
  }
}

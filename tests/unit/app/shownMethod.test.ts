import { describe, expect, it } from 'vitest';
import { shownMethod } from '../../../src/app/shownMethod.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';

describe('the method the app draws', () => {
  it('fourier with a dispersive film draws with the table, and the notice names the film and both modes', () => {
    for (const nFilm of ['water', { cauchy: [1.45, 6000, 0] }] as const) {
      const asked = { ...DEFAULT_SETTINGS, mode: 'fourier' as const, nFilm };
      const { settings, notice } = shownMethod(asked);
      expect(settings).toEqual({ ...asked, mode: 'table' });
      expect(notice).toContain('mode=fourier');
      expect(notice).toContain('mode=table');
      expect(notice).toContain(nFilm === 'water' ? 'nFilm=water' : 'nFilm=cauchy:1.45,6000');
    }
  });

  it('every other pair of mode and film is drawn as asked, without a notice', () => {
    for (const mode of ['exact', 'table', 'fourier', 'three-iridescence'] as const)
      for (const nFilm of [1.33, 'water'] as const) {
        if (mode === 'fourier' && nFilm === 'water') continue;
        const asked = { ...DEFAULT_SETTINGS, mode, nFilm };
        expect(shownMethod(asked)).toEqual({ settings: asked, notice: null });
      }
  });
});

import { describe, expect, it } from 'vitest';
import { shownMethod } from '../../../src/app/shownMethod.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { methodReads } from '../../../src/methods/methods.ts';

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

  it('fourier over a tabulated metal draws with the table too, the notice naming the inside; a constant complex inside keeps its series', () => {
    const metal = { ...DEFAULT_SETTINGS, mode: 'fourier' as const, nInside: 'Au' as const };
    const { settings, notice } = shownMethod(metal);
    expect(settings).toEqual({ ...metal, mode: 'table' });
    expect(notice).toContain('nInside=Au');
    const constant = { ...DEFAULT_SETTINGS, mode: 'fourier' as const, nInside: { complex: [0.43, 2.455] as const } };
    expect(shownMethod(constant)).toEqual({ settings: constant, notice: null });
  });

  it('every other pair of mode and film is drawn as asked, without a notice', () => {
    for (const mode of ['exact', 'table', 'fourier', 'three-iridescence'] as const)
      for (const nFilm of [1.33, 'water'] as const) {
        // A series in the optical path alone has no form for a dispersive film (the case above).
        if (methodReads(mode, 'spectralTransform') && nFilm === 'water') continue;
        const asked = { ...DEFAULT_SETTINGS, mode, nFilm };
        expect(shownMethod(asked)).toEqual({ settings: asked, notice: null });
      }
  });
});

/** The film-level part of what is drawn (src/settings/drawnFilm.ts): the same rule for the demo's view and for a material. */
import { describe, expect, it } from 'vitest';
import { parseLayers } from '../../../src/physics/stackText.ts';
import { drawnFilmMethod } from '../../../src/settings/drawnFilm.ts';

const FILM = { mode: 'fourier', nFilm: 1.33, nInside: 1, illuminant: 'D65' } as const;
const STACK = parseLayers('layers', '(2.35:56.6/1.46:91.1)*8');

describe('which method draws a film, and why', () => {
  it('a stack in `fourier` (which has no form for one) is drawn by the table for either drawer, saying why', () => {
    for (const drawer of ['view', 'material'] as const) {
      const { film, notice } = drawnFilmMethod({ ...FILM, layers: STACK }, drawer);
      expect(film).toEqual({ ...FILM, layers: STACK, mode: 'table' });
      expect(notice).toEqual({ key: 'app.stackAsTable', values: { method: 'fourier', count: '16' } });
    }
  });

  it("a dispersive film in `fourier`: the view draws the table (its frame rate), a material its user's method", () => {
    const water = { ...FILM, nFilm: 'water' } as const;
    expect(drawnFilmMethod(water, 'view').film.mode).toBe('table');
    expect(drawnFilmMethod(water, 'material')).toEqual({ film: water, notice: null });
  });

  it('a method that draws the film is kept as asked, the settings untouched', () => {
    for (const mode of ['exact', 'table', 'fourier'] as const) {
      const asked = { ...FILM, mode, layers: [] };
      expect(drawnFilmMethod(asked, 'view')).toEqual({ film: asked, notice: null });
    }
  });

  it('under a line source a table is drawn by `exact`, which sums the lines at any thickness, for either drawer, saying why', () => {
    for (const drawer of ['view', 'material'] as const) {
      for (const [illuminant, text] of [
        ['Na', 'Na'],
        [{ lineNm: 632.8 }, 'line:632.8'],
      ] as const) {
        const { film, notice } = drawnFilmMethod({ ...FILM, mode: 'table', illuminant, layers: [] }, drawer);
        expect(film.mode).toBe('exact');
        expect(notice).toEqual({ key: 'app.linesAsExact', values: { method: 'table', light: text, drawn: 'exact' } });
      }
      // A stack in `fourier` would be drawn by the table: under a line, `exact` draws it.
      expect(drawnFilmMethod({ ...FILM, illuminant: 'Na', layers: STACK }, drawer).film.mode).toBe('exact');
      // `fourier` sums the lines itself; lamps have spectra and keep the table.
      expect(drawnFilmMethod({ ...FILM, illuminant: 'Na', layers: [] }, drawer).notice).toBeNull();
      expect(drawnFilmMethod({ ...FILM, mode: 'table', illuminant: 'FL2', layers: [] }, drawer).notice).toBeNull();
    }
  });
});

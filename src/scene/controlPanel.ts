import GUI from 'lil-gui';
import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { DAYLIGHT_CCT_MAX_K, DAYLIGHT_CCT_MIN_K } from '../physics/illuminants.ts';
import { NORMALIZATIONS } from '../physics/spectralIntegration.ts';
import { ENVIRONMENTS, FIELDS, type FilmSettings, MODES, SIDES, SPACES } from '../render/filmSettings.ts';

/**
 * A lil-gui panel over every scene parameter. Sliders bound the values to the documented ranges,
 * so the panel cannot produce an invalid setting. `onChange` receives the new settings.
 */
export function createControlPanel(initial: FilmSettings, onChange: (s: FilmSettings) => void, container?: HTMLElement): GUI {
  const cct = typeof initial.illuminant === 'object' ? initial.illuminant.daylightCct : 6504;
  const state = {
    ...initial,
    illuminantName: typeof initial.illuminant === 'object' ? 'daylight (CCT)' : initial.illuminant,
    daylightCct: cct,
  };
  const emit = () => {
    const { illuminantName, daylightCct, ...rest } = state;
    onChange({
      ...rest,
      illuminant: illuminantName === 'daylight (CCT)' ? { daylightCct } : (illuminantName as Exclude<FilmSettings['illuminant'], object>),
    });
  };
  const gui = new GUI({ title: 'thin film', ...(container ? { container } : {}) });
  const film = gui.addFolder('film');
  film.add(state, 'field', [...FIELDS]).name('thickness field');
  film.add(state, 'thicknessNm', 0, 3000, 1).name('thickness (nm)');
  film.add(state, 'thicknessRangeNm', 0, 3000, 1).name('range (nm)');
  film.add(state, 'swirlSpeed', 0, 10, 0.05).name('swirl speed');
  film.add(state, 'nFilm', 1, 4, 0.01).name('n film');
  film.add(state, 'nOutside', 1, 4, 0.01).name('n outside');
  film.add(state, 'nInside', 1, 4, 0.01).name('n inside');
  const light = gui.addFolder('light and colour');
  light.add(state, 'illuminantName', ['D55', 'D65', 'D93', 'E', 'D65-table', 'daylight (CCT)']).name('illuminant');
  light.add(state, 'daylightCct', DAYLIGHT_CCT_MIN_K, DAYLIGHT_CCT_MAX_K, 10).name('daylight CCT (K)');
  light.add(state, 'polarization', [...POLARIZATIONS]);
  light.add(state, 'normalization', [...NORMALIZATIONS]);
  light.add(state, 'space', [...SPACES]).name('colour space');
  light.add(state, 'exposure', 0, 4, 0.01);
  const view = gui.addFolder('view');
  view.add(state, 'mode', [...MODES]).name('evaluation');
  view.add(state, 'env', [...ENVIRONMENTS]).name('environment');
  view.add(state, 'sides', [...SIDES]);
  view.add(state, 'animate');
  gui.onChange(emit);
  return gui;
}

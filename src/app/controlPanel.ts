import GUI from 'lil-gui';
import { message } from '../i18n/messages.ts';
import { FILM_MATERIALS, type FilmIndex, filmIndexText, readFilmIndex } from '../physics/filmIndex.ts';
import { FILM_STACK_DOMAIN, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { DAYLIGHT_CCT_DOMAIN_K, type IlluminantSpec, NAMED_ILLUMINANTS, daylightCctOf } from '../physics/illuminants.ts';
import { type Catalogue, EN, type MessageKey } from '../i18n/en.ts';
import { PANEL_FOLDERS, type ParameterRow, choiceKey, labelKey } from '../settings/parameterRow.ts';
import { VIEW_PARAMETERS, type ViewSettings } from '../settings/viewParameters.ts';

/** The panel's choice for an illuminant given by its CCT. */
const DAYLIGHT_CCT = 'daylight';
/** The CCT slider's step. */
const CCT_STEP_K = 10;
/** The film index's kinds in the panel: a constant (the slider), a material, or a Cauchy film (a text A,B[,C]). */
const CONSTANT_INDEX = 'constant';
const CAUCHY_INDEX = 'cauchy';
const INDEX_STEP = 0.01;
/** The Cauchy text a constant or a material starts with: a glass-like film (n 1.49 at 400 nm, 1.46 at 700 nm). */
const CAUCHY_START = '1.45,6000';

/** A parameter whose panel controls are several: they write their own object, and `join` reads the setting off it. */
type Joined = () => Partial<ViewSettings>;

/** A list's options for lil-gui: each value under its label in the catalogue (`choice.<key>.<value>`). */
const options = (cat: Catalogue, key: string, values: readonly string[]): Record<string, string> =>
  Object.fromEntries(values.map((v) => [cat[choiceKey(key, v)] ?? v, v]));

/**
 * A lil-gui panel over every parameter the schema (VIEW_PARAMETERS) gives a control, grouped in
 * its folders. Sliders span each parameter's whole domain, so the panel cannot produce an invalid
 * setting and reaches every valid one. `onChange` receives the new settings.
 */
export function createControlPanel(
  initial: ViewSettings,
  onChange: (s: ViewSettings) => void,
  container?: HTMLElement,
  cat: Catalogue = EN,
): GUI {
  const state: Record<string, unknown> = { ...initial };
  const joins: Joined[] = [];
  const emit = () => {
    let next: ViewSettings = { ...initial, ...(state as Partial<ViewSettings>) };
    for (const join of joins) next = { ...next, ...join() };
    onChange(next);
  };
  const gui = new GUI({ title: cat['panel.title'], ...(container ? { container } : {}) });
  for (const folderName of PANEL_FOLDERS) {
    const folder = gui.addFolder(cat[`panel.folder.${folderName}` as MessageKey]);
    for (const row of VIEW_PARAMETERS.filter((r) => r.control?.folder === folderName)) {
      const join = addControl(folder, row, state, cat);
      if (join) joins.push(join);
    }
  }
  gui.onChange(emit);
  return gui;
}

function addControl(folder: GUI, row: ParameterRow<ViewSettings>, state: Record<string, unknown>, cat: Catalogue): Joined | null {
  const control = row.control!;
  const label = cat[labelKey(row.key)];
  switch (control.kind) {
    case 'slider':
      folder.add(state, row.key, control.min, control.max, control.step).name(label);
      return null;
    case 'choice':
      folder.add(state, row.key, options(cat, row.key, control.choices)).name(label);
      return null;
    case 'toggle':
      folder.add(state, row.key).name(label);
      return null;
    case 'illuminant': {
      const spec = state[row.key] as IlluminantSpec;
      const pair = {
        name: typeof spec === 'object' ? DAYLIGHT_CCT : spec,
        // A named daylight starts the slider at its own CCT; E and the D65 table at D65's.
        cct: Math.round(daylightCctOf(spec) ?? daylightCctOf('D65')!),
      };
      folder.add(pair, 'name', options(cat, row.key, [...NAMED_ILLUMINANTS, DAYLIGHT_CCT])).name(label);
      folder.add(pair, 'cct', DAYLIGHT_CCT_DOMAIN_K.min, DAYLIGHT_CCT_DOMAIN_K.max, CCT_STEP_K).name(cat['panel.daylightCct']);
      return () => ({ [row.key]: pair.name === DAYLIGHT_CCT ? { daylightCct: pair.cct } : (pair.name as IlluminantSpec) });
    }
    case 'filmIndex':
      return addFilmIndexControls(folder, row, state[row.key] as FilmIndex, cat);
  }
}

/**
 * A film index: a list (constant, the materials, cauchy), the constant's slider, and the Cauchy
 * film's A,B[,C] as text. A Cauchy text that is not one, or leaves the index domain, is not taken:
 * the last good index stays (and the text field says why in its title).
 */
function addFilmIndexControls(folder: GUI, row: ParameterRow<ViewSettings>, initial: FilmIndex, cat: Catalogue): Joined {
  const { min, max } = FILM_STACK_DOMAIN.nFilm;
  const controls = {
    kind: typeof initial === 'number' ? CONSTANT_INDEX : typeof initial === 'string' ? initial : CAUCHY_INDEX,
    n: typeof initial === 'number' ? initial : SOAP_FILM_IN_AIR.nFilm,
    cauchy: typeof initial === 'object' ? filmIndexText(initial).slice(`${CAUCHY_INDEX}:`.length) : CAUCHY_START,
  };
  let good = initial;
  folder.add(controls, 'kind', options(cat, row.key, [CONSTANT_INDEX, ...FILM_MATERIALS, CAUCHY_INDEX])).name(cat['panel.filmMaterial']);
  folder.add(controls, 'n', min, max, INDEX_STEP).name(cat[labelKey(row.key)]);
  const text = folder.add(controls, 'cauchy').name(cat['panel.cauchy']);
  return () => {
    if (controls.kind === CONSTANT_INDEX) good = controls.n;
    else if (controls.kind !== CAUCHY_INDEX) good = controls.kind as FilmIndex;
    else {
      const reading = readFilmIndex(`${CAUCHY_INDEX}:${controls.cauchy}`);
      if ('index' in reading) good = reading.index;
      text.domElement.title = 'problem' in reading ? message(cat, 'panel.notTaken', { problem: reading.problem }) : '';
    }
    return { [row.key]: good };
  };
}

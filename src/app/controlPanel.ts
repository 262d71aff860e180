import GUI, { type Controller } from 'lil-gui';
import { message } from '../i18n/messages.ts';
import { FILM_MATERIALS } from '../physics/filmIndex.ts';
import type { FilmLayer } from '../physics/stackFilms.ts';
import { layersText } from '../physics/stackText.ts';
import { readStackField } from './stackField.ts';
import { CAUCHY_INDEX, COMPLEX_INDEX, CONSTANT_INDEX, TEXT_KINDS, mediumKind, shownControls } from './shownControls.ts';
import { type Medium, type MediumRole, mediumExpected, mediumText, readMedium } from '../physics/medium.ts';
import { NAMED_MEDIA } from '../physics/namedMedia.ts';
import { FILM_STACK_DOMAIN, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { DAYLIGHT_CCT_DOMAIN_K, type IlluminantSpec, NAMED_ILLUMINANTS, daylightCctOf, illuminantLines } from '../physics/illuminants.ts';
import { LINE_DOMAIN_NM, SODIUM_D_LINES } from '../physics/lightLines.ts';
import type { LightTint } from '../physics/lightTint.ts';
import type { Environment } from '../environments/environments.ts';
import { addEnvironmentControl, addTintControl } from './colorControls.ts';
import { type Catalogue, EN, type MessageKey } from '../i18n/en.ts';
import { AUTO, type Auto, PANEL_FOLDERS, type PanelFolder, type ParameterRow, choiceKey, labelKey } from '../settings/parameterRow.ts';
import { VIEW_PARAMETERS, type ViewSettings } from '../settings/viewParameters.ts';

/** The panel's choice for an illuminant given by its CCT. */
const DAYLIGHT_CCT = 'daylight';
/** The panel's choice for a single line given by its wavelength. */
const SINGLE_LINE = 'line';
/** The CCT slider's step. */
const CCT_STEP_K = 10;
/** The line slider's step. */
const LINE_STEP_NM = 0.1;
const INDEX_STEP = 0.01;
/** The Cauchy text a constant or a material starts with: a glass-like film (n 1.49 at 400 nm, 1.46 at 700 nm). */
const CAUCHY_START = '1.45,6000';
/** The complex text the others start with: gold at 548.6 nm (Johnson & Christy), ñ = 0.43 + 2.455i. */
const COMPLEX_START = '0.43,2.455';

/** A parameter whose panel controls are several: they write their own object, and `join` reads the setting off it. */
type Joined = () => Partial<ViewSettings>;

/** A medium's list and text fields: the kind chosen in the list, and the text field of each kind it offers as text. */
interface MediumControls {
  readonly kind: () => string;
  readonly texts: readonly { readonly kind: string; readonly field: Controller }[];
}

/** What a row adds to the panel besides its controllers: its join, and a medium's list and text fields. */
interface RowParts {
  readonly join?: Joined;
  readonly medium?: MediumControls;
  /** Whether a controller of the row is shown while the row is (an `auto` row's slider only while `auto` is off). */
  readonly shows?: (c: Controller) => boolean;
}

/** A list's options for lil-gui: each value under its label in the catalogue (`choice.<key>.<value>`). */
const options = (cat: Catalogue, key: string, values: readonly string[]): Record<string, string> =>
  Object.fromEntries(values.map((v) => [cat[choiceKey(key, v)] ?? v, v]));

const FLOW_ACTIONS = ['blow', 'burst'] as const;
/** The flow folder's buttons, each named `panel.<action>`: blow at the probe and burst the film there, what B and P on the bubble do. */
export type FlowActions = Readonly<Record<(typeof FLOW_ACTIONS)[number], () => void>>;

/**
 * A lil-gui panel over every parameter the schema (VIEW_PARAMETERS) gives a control, grouped in
 * its folders. Sliders span each parameter's whole domain, so the panel cannot produce an invalid
 * setting and reaches every valid one. It shows only what applies to the settings
 * (shownControls.ts), after every change; what it hides keeps its value. `onChange` receives the
 * new settings; `actions`, if given, are the flow folder's buttons (FlowActions);
 * `filmTime`, if given, the flow folder's read-only line on the film's time and grid as the frame
 * governor keeps them (followed while the panel is shown).
 */
export function createControlPanel(
  initial: ViewSettings,
  onChange: (s: ViewSettings) => void,
  container?: HTMLElement,
  cat: Catalogue = EN,
  actions?: FlowActions,
  filmTime?: () => string,
): GUI {
  const state: Record<string, unknown> = { ...initial };
  const rows: { readonly key: keyof ViewSettings; readonly controllers: readonly Controller[]; readonly parts: RowParts }[] = [];
  const folders = new Map<PanelFolder, GUI>();
  /** Shows what applies to `s` (with each medium's kind as its list has it), hides the rest. */
  const show = (s: ViewSettings) => {
    const kinds = Object.fromEntries(rows.flatMap(({ key, parts }) => (parts.medium ? [[key, parts.medium.kind()]] : [])));
    const shown = shownControls(s, kinds);
    for (const { key, controllers, parts } of rows) {
      const texts = new Map(parts.medium?.texts.map((t) => [t.field, t.kind]));
      for (const c of controllers) {
        c.show(texts.has(c) ? shown.texts[key] === texts.get(c) : shown.rows[key] && (parts.shows?.(c) ?? true));
      }
    }
    for (const [name, folder] of folders) folder.show(shown.folders[name]);
  };
  const emit = () => {
    let next: ViewSettings = { ...initial, ...(state as Partial<ViewSettings>) };
    for (const { parts } of rows) if (parts.join) next = { ...next, ...parts.join() };
    show(next);
    onChange(next);
  };
  const gui = new GUI({ title: cat['panel.title'], ...(container ? { container } : {}) });
  for (const folderName of PANEL_FOLDERS) {
    const folder = gui.addFolder(cat[`panel.folder.${folderName}` as MessageKey]);
    folders.set(folderName, folder);
    for (const row of VIEW_PARAMETERS.filter((r) => r.control?.folder === folderName)) {
      const before = folder.controllers.length;
      const parts = addControl(folder, row, state, cat);
      rows.push({ key: row.key, controllers: folder.controllers.slice(before), parts });
    }
    if (folderName === 'flow' && actions) for (const name of FLOW_ACTIONS) folder.add(actions, name).name(cat[`panel.${name}`]);
    if (folderName === 'flow' && filmTime) {
      // A read-only line followed while shown (lil-gui's listen), never a setting.
      const status = Object.defineProperty({}, 'line', { get: filmTime, set: () => {}, enumerable: true }) as { line: string };
      folder.add(status, 'line').name(cat['panel.governor']).disable().listen();
    }
  }
  show(initial);
  gui.onChange(emit);
  return gui;
}

function addControl(folder: GUI, row: ParameterRow<ViewSettings>, state: Record<string, unknown>, cat: Catalogue): RowParts {
  const control = row.control!;
  const label = cat[labelKey(row.key)];
  switch (control.kind) {
    case 'slider':
      folder.add(state, row.key, control.min, control.max, control.step).name(label);
      return {};
    case 'choice':
      folder.add(state, row.key, options(cat, row.key, control.choices)).name(label);
      return {};
    case 'toggle':
      folder.add(state, row.key).name(label);
      return {};
    case 'illuminant': {
      const spec = state[row.key] as IlluminantSpec;
      const lineNm = illuminantLines(spec)?.[0]?.nm;
      const pair = {
        name: typeof spec !== 'object' ? spec : 'lineNm' in spec ? SINGLE_LINE : DAYLIGHT_CCT,
        // A named daylight starts the slider at its own CCT; the other lights at D65's.
        cct: Math.round(daylightCctOf(spec) ?? daylightCctOf('D65')!),
        // A line source starts the line's slider at its (first) line; the other lights at sodium's D2.
        lineNm: lineNm ?? SODIUM_D_LINES[0]!.nm,
      };
      folder.add(pair, 'name', options(cat, row.key, [...NAMED_ILLUMINANTS, DAYLIGHT_CCT, SINGLE_LINE])).name(label);
      folder.add(pair, 'cct', DAYLIGHT_CCT_DOMAIN_K.min, DAYLIGHT_CCT_DOMAIN_K.max, CCT_STEP_K).name(cat['panel.daylightCct']);
      folder.add(pair, 'lineNm', LINE_DOMAIN_NM.min, LINE_DOMAIN_NM.max, LINE_STEP_NM).name(cat['panel.lineNm']);
      const chosen = (): IlluminantSpec =>
        pair.name === DAYLIGHT_CCT
          ? { daylightCct: pair.cct }
          : pair.name === SINGLE_LINE
            ? { lineNm: pair.lineNm }
            : (pair.name as IlluminantSpec);
      return { join: () => ({ [row.key]: chosen() }) };
    }
    case 'tint':
      return { join: addTintControl(folder, row, state[row.key] as LightTint, cat) };
    case 'environment':
      return addEnvironmentControl(folder, row, state[row.key] as Environment, cat);
    case 'filmIndex':
      return addMediumControls(folder, row, state[row.key] as Medium, cat, FILM_INDEX_KINDS, 'film');
    case 'medium':
      return addMediumControls(
        folder,
        row,
        state[row.key] as Medium,
        cat,
        control.role === 'film' ? FILM_MEDIUM_KINDS : INSIDE_MEDIUM_KINDS,
        control.role,
      );
    case 'stack':
      return { join: addStackControl(folder, row, state[row.key] as readonly FilmLayer[], cat) };
    case 'auto':
      return addAutoControl(folder, row, control, state[row.key] as Auto<number>, cat);
  }
}

/**
 * `auto` or a number: a toggle (on: `auto`, the frame governor's) and a slider over the whole
 * domain, shown while the toggle is off; it starts at the value given, else at the row's start.
 */
function addAutoControl(
  folder: GUI,
  row: ParameterRow<ViewSettings>,
  control: { readonly min: number; readonly max: number; readonly step: number; readonly start: number },
  initial: Auto<number>,
  cat: Catalogue,
): RowParts {
  const label = cat[labelKey(row.key)];
  const controls = { auto: initial === AUTO, value: initial === AUTO ? control.start : initial };
  folder.add(controls, 'auto').name(message(cat, 'panel.auto', { label }));
  const slider = folder.add(controls, 'value', control.min, control.max, control.step).name(label);
  return { join: () => ({ [row.key]: controls.auto ? AUTO : controls.value }), shows: (c) => c !== slider || !controls.auto };
}

/**
 * A stack of films as text (stackText.ts; empty: the single film). A text that is not one is not
 * taken: the last good stack stays, and the field says why in its title. While a stack is set, the
 * film index's controls are hidden (shownControls.ts): the stack's films carry their own indices.
 */
function addStackControl(folder: GUI, row: ParameterRow<ViewSettings>, initial: readonly FilmLayer[], cat: Catalogue): Joined {
  const controls = { text: layersText(initial) };
  let good = initial;
  const field = folder.add(controls, 'text').name(cat[labelKey(row.key)]);
  return () => {
    const reading = readStackField(row, controls.text, good, cat);
    good = reading.films;
    field.domElement.title = reading.title;
    return { [row.key]: good };
  };
}

/**
 * The list's kinds: of a film index; of a film medium (the named media too: an oxide, an absorbing
 * film); of the inside (the named media and a complex constant n,k: a metal). Each text field is
 * then in one list only. What a list leaves out (a Cauchy inside, a complex film) is still read
 * from the URL, and the panel keeps it until another kind is chosen.
 */
const FILM_INDEX_KINDS = [CONSTANT_INDEX, ...FILM_MATERIALS, CAUCHY_INDEX];
const FILM_MEDIUM_KINDS = [CONSTANT_INDEX, ...FILM_MATERIALS, ...NAMED_MEDIA, CAUCHY_INDEX];
const INSIDE_MEDIUM_KINDS = [CONSTANT_INDEX, ...FILM_MATERIALS, ...NAMED_MEDIA, COMPLEX_INDEX];

/**
 * A medium: a list (constant, the materials, the named media, cauchy, complex: those of `kinds`),
 * the constant's slider, and the Cauchy film's A,B[,C] and the complex constant's n,k as text, each
 * text field shown while its kind is chosen (shownControls.ts). A text that is not one, or leaves
 * its domain, is not taken: the last good medium stays (and the text field says why in its title).
 */
function addMediumControls(
  folder: GUI,
  row: ParameterRow<ViewSettings>,
  initial: Medium,
  cat: Catalogue,
  kinds: readonly string[],
  role: MediumRole,
): RowParts {
  const { min, max } = FILM_STACK_DOMAIN.nFilm;
  const kind = mediumKind(initial);
  const tail = (prefix: string, start: string) => (kind === prefix ? mediumText(initial).slice(`${prefix}:`.length) : start);
  const controls = {
    kind,
    n: typeof initial === 'number' ? initial : SOAP_FILM_IN_AIR.nFilm,
    [CAUCHY_INDEX]: tail(CAUCHY_INDEX, CAUCHY_START),
    [COMPLEX_INDEX]: tail(COMPLEX_INDEX, COMPLEX_START),
  };
  let good = initial;
  folder.add(controls, 'kind', options(cat, row.key, kinds)).name(cat[role === 'inside' ? 'panel.insideMedium' : 'panel.filmMaterial']);
  folder.add(controls, 'n', min, max, INDEX_STEP).name(cat[labelKey(row.key)]);
  const texts = TEXT_KINDS.filter((k) => kinds.includes(k)).map((k) => ({
    kind: k,
    field: folder.add(controls, k as typeof CAUCHY_INDEX).name(cat[k === CAUCHY_INDEX ? 'panel.cauchy' : 'panel.complex']),
  }));
  const join = () => {
    const text = texts.find((t) => t.kind === controls.kind);
    if (controls.kind === CONSTANT_INDEX) good = controls.n;
    else if (!TEXT_KINDS.includes(controls.kind)) good = controls.kind as Medium;
    else if (text) {
      const reading = readMedium(`${text.kind}:${controls[text.kind as typeof CAUCHY_INDEX]}`, role);
      if ('medium' in reading) good = reading.medium;
      const problem = 'problem' in reading ? (reading.problem ?? mediumExpected(role)) : null;
      text.field.domElement.title = problem ? message(cat, 'panel.notTaken', { problem }) : '';
    }
    return { [row.key]: good };
  };
  return { join, medium: { kind: () => controls.kind, texts } };
}

import { parameterNamed, readParameter, settingsToQuery } from '../settings/settingsQuery.ts';
import { VIEW_PARAMETERS, type ViewSettings } from '../settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../settings/demoView.ts';
import { MAX_PIXEL_RATIO } from '../settings/pixelRatio.ts';
import { parseDecimal, describeValue, isInDomain, ParameterError, rejectValue } from '../input/validate.ts';
import { readFlags, urlSpellings } from './readFlags.ts';
import { mediumFromJson, mediumText } from '../physics/medium.ts';
import { parseJsonArray } from './parseJsonArray.ts';
import { type TimeLapseFormat, checkTimeLapseSize, frameMs, timeLapseFormat, timeLapseTimes } from './timeLapseOptions.ts';

/** One picture to render: the demo at `query`, in a `widthPx` × `heightPx` CSS-pixel window. */
export interface RenderView {
  /** The PNG file to write. */
  readonly out: string;
  readonly widthPx: number;
  readonly heightPx: number;
  /** Device pixels per CSS pixel: the PNG is `scale` times the window. */
  readonly scale: number;
  /** Whether the plots at the probe are drawn beside the bubble. */
  readonly plots: boolean;
  /** The demo page's URL query for the view (the schema's parameters; defaults left out). */
  readonly query: string;
}

/** The picture's own options, beside the view's parameters (the schema's, `--name value`). */
export const PICTURE_OPTIONS = {
  width: { min: 16, max: 4096, unit: 'CSS px', fallback: 640, whole: true },
  height: { min: 16, max: 4096, unit: 'CSS px', fallback: 480, whole: true },
  // The demo draws at most MAX_PIXEL_RATIO device pixels per CSS pixel.
  scale: { min: 1, max: MAX_PIXEL_RATIO, unit: '', fallback: 1, whole: false },
} as const;
type PictureNumber = keyof typeof PICTURE_OPTIONS;
const PICTURE_NUMBERS = Object.keys(PICTURE_OPTIONS) as PictureNumber[];

/**
 * What a view may set: the picture's options and the schema's parameters, these by their URL names
 * (as a cases file writes them; the command line's flags are the same names in kebab case).
 */
export const VIEW_FIELDS: readonly string[] = ['out', ...PICTURE_NUMBERS, 'plots', ...VIEW_PARAMETERS.map((row) => row.url)];

/** A view's field as the command line spells it: `--thickness-range` for `thicknessRange`. */
export const flagOfField = (name: string): string => `--${parameterNamed(name)?.flag ?? name}`;

/** The command line's value flags and switches: the view's fields, and the command's own. */
const VALUE_FLAGS = ['out', ...PICTURE_NUMBERS, ...VIEW_PARAMETERS.map((row) => row.flag), 'cases', 'time-lapse', 'frame-ms'];
const FLAG_SPEC = { values: VALUE_FLAGS, switches: ['plots', 'progress', 'help'], spellings: urlSpellings(VALUE_FLAGS) };
const FIELD_OF_FLAG = new Map(VIEW_PARAMETERS.map((row) => [row.flag, row.url]));
const clash = [...VALUE_FLAGS, ...FLAG_SPEC.switches].find((name, i, all) => all.indexOf(name) !== i);
if (clash) throw new Error(`render: the option --${clash} is both a view parameter and one of the picture's options`);

const expectedPictureNumber = (name: PictureNumber): string => {
  const o = PICTURE_OPTIONS[name];
  return `${o.whole ? 'a whole number' : 'a number'} in [${o.min}, ${o.max}]${o.unit ? ` ${o.unit}` : ''}`;
};

/** What each field of a view accepts, as its refusal says. */
export function expectedOf(name: string): string {
  if (name === 'out') return 'the path of the PNG file to write';
  if (name === 'plots') return 'true or false (on the command line: --plots, no value)';
  if (name in PICTURE_OPTIONS) return expectedPictureNumber(name as PictureNumber);
  return parameterNamed(name)!.expected;
}

/** What the command renders, and whether it reports progress where stderr is not a terminal (`--progress`). */
export type RenderCommand =
  | { readonly kind: 'help' }
  | { readonly kind: 'views'; readonly views: readonly RenderView[]; readonly progress: boolean }
  /** `--cases FILE`: the file's views, each over `defaults` (the command line's other options). */
  | { readonly kind: 'casesFile'; readonly path: string; readonly defaults: RawView; readonly progress: boolean }
  /**
   * `--time-lapse START:END:STEP`: one animation written to `out`, frame i the view frozen at
   * `timesS[i]` (its `frames[i]`, animate 0), each shown for `frameMs`.
   */
  | {
      readonly kind: 'timeLapse';
      readonly progress: boolean;
      readonly out: string;
      readonly format: TimeLapseFormat;
      readonly timesS: readonly number[];
      readonly frames: readonly RenderView[];
      readonly frameMs: number;
    };

type TimeLapseCommand = Extract<RenderCommand, { kind: 'timeLapse' }>;

/** A view's fields as given (by their URL names): text from the command line, JSON values from a cases file. */
type RawView = ReadonlyMap<string, unknown>;

/**
 * What the render command's arguments ask for, every value checked: a ParameterError naming the
 * first bad option and what it accepts. The view's options are the schema's rows, read as the URL reads them.
 */
export function parseRenderCommandLine(argv: readonly string[]): RenderCommand {
  const { values, switches } = readFlags(argv, FLAG_SPEC);
  if (switches.has('help')) return { kind: 'help' };
  const progress = switches.has('progress');
  // The view's fields by their URL names, as a cases file gives them.
  const given = new Map<string, unknown>([...values].map(([flag, text]) => [FIELD_OF_FLAG.get(flag) ?? flag, text]));
  if (switches.has('plots')) given.set('plots', true);
  if (given.has('cases')) {
    const lapseFlag = ['time-lapse', 'frame-ms'].find((name) => given.has(name));
    if (lapseFlag)
      throw new ParameterError(`--${lapseFlag}`, `--${lapseFlag}: not allowed with --cases (a time-lapse is one view at many times)`);
    const { cases: path, ...rest } = Object.fromEntries(given) as { cases: string };
    if (given.has('out')) throw new ParameterError('--out', '--out: not allowed with --cases (each view in the file names its own out)');
    if (path === '') return rejectValue('--cases', path, 'the path of a JSON file');
    const defaults = new Map(Object.entries(rest));
    readView(defaults, flagOfField, false); // the options every view shares are checked before the file is read
    return { kind: 'casesFile', path, defaults, progress };
  }
  if (given.has('time-lapse') || given.has('frame-ms')) return { ...timeLapseCommand(given), progress };
  return { kind: 'views', views: [readView(given, flagOfField, true)], progress };
}

/** A time-lapse: the view of the other options, checked, then frozen (animate 0) at each time of `--time-lapse`. */
function timeLapseCommand(given: RawView): Omit<TimeLapseCommand, 'progress'> {
  const { 'time-lapse': lapse, 'frame-ms': ms, ...rest } = Object.fromEntries(given) as { 'time-lapse'?: string; 'frame-ms'?: string };
  if (lapse === undefined) {
    throw new ParameterError('--frame-ms', '--frame-ms: not allowed without --time-lapse (it is the time each frame is shown)');
  }
  if (given.has('time')) {
    throw new ParameterError('--time-lapse', '--time-lapse: not allowed with --time (each frame is frozen at its own time)');
  }
  if (given.get('animate') === '1') {
    throw new ParameterError('--time-lapse', '--time-lapse: not allowed with --animate 1 (each frame is a frozen view, animate 0)');
  }
  const fields = new Map(Object.entries(rest));
  const { out, widthPx, heightPx, scale } = readView(fields, flagOfField, true);
  const format = timeLapseFormat(out);
  const timesS = timeLapseTimes(lapse);
  checkTimeLapseSize(timesS.length, Math.round(widthPx * scale) * Math.round(heightPx * scale));
  const shownMs = frameMs(ms);
  const frames = timesS.map((t) => readView(new Map([...fields, ['animate', '0'], ['time', String(t)]]), flagOfField, true));
  return { kind: 'timeLapse', out, format, timesS, frames, frameMs: shownMs };
}

/**
 * The views of a `--cases` file: a JSON array of objects `{ "out", ...fields }` with the fields of
 * VIEW_FIELDS, each over `defaults`; every view is checked before any is rendered, and two may
 * not write the same file. The first bad one throws a ParameterError naming the case's index and the field.
 */
export function parseRenderCases(text: string, fileName: string, defaults: RawView): RenderView[] {
  const outs = new Map<string, number>();
  return parseJsonArray(text, fileName, 'views').map((entry, index) => {
    try {
      if (typeof entry !== 'object' || entry === null || Array.isArray(entry)) {
        return rejectValue('case', entry, `an object { "out", ... } with some of the fields ${VIEW_FIELDS.join(', ')}`);
      }
      const fields = new Map(Object.entries(entry));
      const unknown = [...fields.keys()].find((name) => !VIEW_FIELDS.includes(name));
      if (unknown !== undefined) {
        throw new ParameterError(unknown, `${describeValue(unknown)}: unknown field; expected one of ${VIEW_FIELDS.join(', ')}`);
      }
      // A field is named as the case writes it, or as the command line does where the value came from there.
      const field = (name: string) => (!fields.has(name) && defaults.has(name) ? flagOfField(name) : name);
      const view = readView(new Map([...defaults, ...fields]), field, true);
      const earlier = outs.get(view.out);
      if (earlier !== undefined) rejectValue('out', view.out, `a file no other view writes (case at index ${earlier} does)`);
      outs.set(view.out, index);
      return view;
    } catch (error) {
      if (!(error instanceof ParameterError)) throw error;
      throw new ParameterError(error.parameter, `case at index ${index}: ${error.message}`);
    }
  });
}

/** A medium written as a cases file's object (`{ "complex": [n, k] }`, `{ "cauchy": [A, B] }`) in the URL's words, or null. */
function jsonMediumText(value: unknown): string | null {
  if (typeof value !== 'object' || value === null) return null;
  const medium = mediumFromJson(value);
  return medium === null ? null : mediumText(medium);
}

/** A view from its fields (`field` names one in messages), checked; `needsOut`: a missing out is refused. */
function readView(fields: RawView, field: (name: string) => string, needsOut: true): RenderView;
function readView(fields: RawView, field: (name: string) => string, needsOut: false): null;
function readView(fields: RawView, field: (name: string) => string, needsOut: boolean): RenderView | null {
  // The demo's default view, which its URL leaves out (demoView.ts).
  let settings: ViewSettings = DEMO_VIEW_SETTINGS;
  for (const row of VIEW_PARAMETERS) {
    if (!fields.has(row.url)) continue;
    const value = fields.get(row.url);
    const raw = typeof value === 'string' ? value : typeof value === 'number' ? String(value) : jsonMediumText(value);
    const reading = raw === null ? null : readParameter(row, raw);
    if (reading === null || !('read' in reading)) {
      return rejectValue(field(row.url), value, reading?.expected ?? `${row.expected}, as a string or a number`);
    }
    settings = { ...settings, ...reading.read };
  }
  const [widthPx, heightPx, scale] = PICTURE_NUMBERS.map((name) => pictureNumber(name, fields.get(name), field(name)));
  const plots = fields.get('plots') ?? false;
  if (typeof plots !== 'boolean') rejectValue(field('plots'), plots, expectedOf('plots'));
  const out = fields.get('out');
  if (out === undefined && !needsOut) return null;
  if (typeof out !== 'string' || out === '') return rejectValue(field('out'), out, expectedOf('out'));
  return { out, widthPx: widthPx!, heightPx: heightPx!, scale: scale!, plots, query: settingsToQuery(settings, DEMO_VIEW_SETTINGS) };
}

function pictureNumber(name: PictureNumber, value: unknown, field: string): number {
  const option = PICTURE_OPTIONS[name];
  if (value === undefined) return option.fallback;
  const v = typeof value === 'string' ? parseDecimal(value) : value;
  return isInDomain(v, option) && (!option.whole || Number.isInteger(v)) ? v : rejectValue(field, value, expectedPictureNumber(name));
}

import { isInDomain, type NumberDomain, parseDecimal } from '../input/validate.ts';
import { FILM_PARAMETERS, flowParameterRow } from './filmParameters.ts';
import type { FilmSettings } from './filmSettings.ts';
import { AUTO, type Auto, type ParameterRow, customRow, defaultsOf } from './parameterRow.ts';
import { autoNumberRow, flagRow } from './valueRows.ts';

/**
 * The knobs a page may leave to its frame governor (docs/governor.md): `auto`, or a value a user
 * gave (URL, attribute, panel), honoured exactly. With `auto` a frozen view draws the film's
 * default grid (FILM_PARAMETERS), at simulation speed 1, at the device's pixel ratio (at most
 * MAX_PIXEL_RATIO: pixelRatio.ts).
 */
export interface GovernedSettings {
  /** The flowing film's grid (FLOW_PARAMETERS' `gridN`). */
  readonly gridN: Auto<number>;
  /** Film seconds per second: given, the film follows the clock at exactly this speed. */
  readonly simSpeed: Auto<number>;
  /** The drawing buffer's pixels per CSS pixel. */
  readonly pixelRatio: Auto<number>;
}

/** What the page adds to the rendered view: the frame loop and where the plots probe. */
export interface AppSettings {
  /** Whether the swirl moves with the clock (off: a frozen frame at `timeSeconds`). */
  readonly animate: boolean;
  /** Where the plots probe the view: fractions of its width and height from the top left. */
  readonly probe: readonly [number, number];
}

/** Everything a bubble on a page shows: the rendered film (its governed knobs as asked) and the page's own settings. */
export type ViewSettings = Omit<FilmSettings, keyof GovernedSettings> & GovernedSettings & AppSettings;

const FRACTION: NumberDomain = { min: 0, max: 1, unit: '' };
/** A pixel ratio a user may give: a quarter of the CSS pixels' density to four times it. */
export const PIXEL_RATIO_DOMAIN: NumberDomain = { min: 0.25, max: 4, unit: '' };

/** The probe: `x,y`, each a fraction of the view. */
const probeRow = customRow<ViewSettings, 'probe'>({ key: 'probe', url: 'probe' }, [0.5, 0.5], {
  expects: { key: 'expected.probe' },
  read: (raw) => {
    const parts = raw.split(',').map(parseDecimal);
    const [x, y] = parts;
    return parts.length === 2 && isInDomain(x, FRACTION) && isInDomain(y, FRACTION) ? { probe: [x, y] } : null;
  },
  write: (s) => s.probe.map((v) => +v.toFixed(4)).join(','),
  control: null,
});

/** A governed flow row: `auto` or a value in its FLOW_PARAMETERS domain, under the film row's URL name. */
function governedFlowRow(key: 'gridN' | 'simSpeed'): ParameterRow<ViewSettings> {
  const film = FILM_PARAMETERS.find((r) => r.key === key)!;
  const flow = flowParameterRow(key);
  const step = film.control?.kind === 'slider' ? film.control.step : 'integer';
  return autoNumberRow<ViewSettings, typeof key>(
    { key, url: film.url },
    flow.domain,
    'flow',
    flow.integer ? 'integer' : step,
    flow.defaultValue,
  );
}

const GOVERNED_FLOW_ROWS: Readonly<Record<string, ParameterRow<ViewSettings>>> = {
  gridN: governedFlowRow('gridN'),
  simSpeed: governedFlowRow('simSpeed'),
};

/** The schema of every user-facing parameter: the film's (its governed ones taking `auto`), then the page's own. */
export const VIEW_PARAMETERS: readonly ParameterRow<ViewSettings>[] = [
  // Each film row, checked field by field as a row of the wider settings.
  ...FILM_PARAMETERS.map(
    (row): ParameterRow<ViewSettings> => GOVERNED_FLOW_ROWS[row.key] ?? (row as unknown as ParameterRow<ViewSettings>),
  ),
  flagRow<ViewSettings, 'animate'>({ key: 'animate', url: 'animate' }, true, 'view'),
  autoNumberRow<ViewSettings, 'pixelRatio'>({ key: 'pixelRatio', url: 'pixelRatio' }, PIXEL_RATIO_DOMAIN, 'view', 0.25, 1),
  probeRow,
];

/** The default view: a swirling soap bubble in daylight, probed at its centre. */
export const DEFAULT_VIEW_SETTINGS: ViewSettings = defaultsOf(VIEW_PARAMETERS);

/** A governed knob's value: the one given, else `chosen` (the governor's), else `fallback`. */
export const governedValue = (given: Auto<number>, chosen: number | undefined, fallback: number): number =>
  given === AUTO ? (chosen ?? fallback) : given;

/**
 * The film settings a view draws for a page's settings: the governed knobs as given, else as the
 * governor chose (`chosen`), else the film's defaults (a frozen view's: FILM_PARAMETERS).
 */
export function filmSettingsOf(s: ViewSettings, chosen: { readonly gridN?: number; readonly simSpeed?: number } = {}): FilmSettings {
  const { animate: _animate, probe: _probe, pixelRatio: _pixelRatio, gridN, simSpeed, ...film } = s;
  const defaults = Object.fromEntries(FILM_PARAMETERS.map((r) => [r.key, r.defaultValue])) as unknown as FilmSettings;
  return {
    ...film,
    gridN: governedValue(gridN, chosen.gridN, defaults.gridN),
    simSpeed: governedValue(simSpeed, chosen.simSpeed, defaults.simSpeed),
  };
}

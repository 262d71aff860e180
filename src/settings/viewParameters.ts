import { isInDomain, type NumberDomain, parseDecimal } from '../input/validate.ts';
import { FILM_PARAMETERS } from './filmParameters.ts';
import type { FilmSettings } from './filmSettings.ts';
import { type ParameterRow, customRow, defaultsOf, flagRow } from './parameterRow.ts';

/** What the page adds to the rendered view: the frame loop and where the plots probe. */
export interface AppSettings {
  /** Whether the swirl moves with the clock (off: a frozen frame at `timeSeconds`). */
  readonly animate: boolean;
  /** Where the plots probe the view: fractions of its width and height from the top left. */
  readonly probe: readonly [number, number];
}

/** Everything a bubble on a page shows: the rendered film and the page's own settings. */
export type ViewSettings = FilmSettings & AppSettings;

const FRACTION: NumberDomain = { min: 0, max: 1, unit: '' };

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

/** The schema of every user-facing parameter: the film's, then the page's own. */
export const VIEW_PARAMETERS: readonly ParameterRow<ViewSettings>[] = [
  // Each film row, checked field by field as a row of the wider settings.
  ...FILM_PARAMETERS.map((row): ParameterRow<ViewSettings> => ({ ...row })),
  flagRow<ViewSettings, 'animate'>({ key: 'animate', url: 'animate' }, true, 'view'),
  probeRow,
];

/** The default view: a swirling soap bubble in daylight, probed at its centre. */
export const DEFAULT_VIEW_SETTINGS: ViewSettings = defaultsOf(VIEW_PARAMETERS);

import { settingApplies } from '../fields/fields.ts';
import type { Medium } from '../physics/medium.ts';
import { PANEL_FOLDERS, type PanelFolder } from '../settings/parameterRow.ts';
import { VIEW_PARAMETERS, type ViewSettings } from '../settings/viewParameters.ts';
import { FILM_FILLS, filmFill } from '../methods/filmFills.ts';

/** A medium's kinds in the panel's list besides the names: a constant (the slider), a Cauchy film (a text A,B[,C]), a complex constant (a text n,k). */
export const CONSTANT_INDEX = 'constant';
export const CAUCHY_INDEX = 'cauchy';
export const COMPLEX_INDEX = 'complex';
/** The kinds a medium's panel control takes as text, each in a text field of its own. */
export const TEXT_KINDS: readonly string[] = [CAUCHY_INDEX, COMPLEX_INDEX];

/** The kind a medium is shown as in the panel's list: constant, its name, cauchy or complex. */
export function mediumKind(m: Medium): string {
  if (typeof m === 'number') return CONSTANT_INDEX;
  if (typeof m === 'string') return m;
  return 'cauchy' in m ? CAUCHY_INDEX : COMPLEX_INDEX;
}

/** The settings a panel row's controls are shown by: its key. */
type PanelKey = keyof ViewSettings;

/** What the panel shows of its rows, folders and medium text fields. */
export interface ShownControls {
  /** Each row with a panel control, by its settings key: whether its controls are shown. */
  readonly rows: Readonly<Record<PanelKey, boolean>>;
  /** Each folder: whether it is shown (whether any of its rows is). */
  readonly folders: Readonly<Record<PanelFolder, boolean>>;
  /** Each medium row, by its key: the kind whose text field is shown (cauchy, complex), or null for none (as while the row is hidden). */
  readonly texts: Readonly<Partial<Record<PanelKey, string | null>>>;
}

const PANEL_ROWS = VIEW_PARAMETERS.filter((row) => row.control !== null);
const MEDIUM_ROWS = PANEL_ROWS.filter((row) => row.control!.kind === 'medium' || row.control!.kind === 'filmIndex');

/**
 * What of the panel applies to the settings `s`, and so is shown:
 * - a setting some thickness field reads, only under the fields that read it (fields.ts,
 *   `settingApplies`): the swirl's speed and range under the swirl, the flow folder under the flow;
 * - a medium's setting only where the film's fill reads it (filmFills.ts: a stack's films carry their own indices);
 * - a medium's Cauchy or complex text field only while its kind is the one chosen: `kinds` gives the
 *   kind chosen in each medium's list where the panel holds one (a text that is not taken leaves the
 *   setting as it was, and its field stays shown to be put right), else the setting's own kind.
 * What is hidden keeps its value: the settings, and so the URL, are the same whatever is shown.
 */
export function shownControls(s: ViewSettings, kinds: Readonly<Partial<Record<PanelKey, string>>> = {}): ShownControls {
  const unused = new Set<PanelKey>(FILM_FILLS[filmFill(s)].unusedSettings);
  const rows = Object.fromEntries(PANEL_ROWS.map((row) => [row.key, settingApplies(row.key, s.field) && !unused.has(row.key)]));
  const folders = Object.fromEntries(
    PANEL_FOLDERS.map((folder) => [folder, PANEL_ROWS.some((row) => row.control!.folder === folder && rows[row.key])]),
  );
  const texts = Object.fromEntries(
    MEDIUM_ROWS.map((row) => {
      const kind = kinds[row.key] ?? mediumKind(s[row.key] as Medium);
      return [row.key, rows[row.key] && TEXT_KINDS.includes(kind) ? kind : null];
    }),
  );
  return { rows: rows as ShownControls['rows'], folders: folders as ShownControls['folders'], texts };
}

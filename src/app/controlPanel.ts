import GUI from 'lil-gui';
import { DAYLIGHT_CCT_DOMAIN_K, type IlluminantSpec, NAMED_ILLUMINANTS, daylightCctOf } from '../physics/illuminants.ts';
import { PANEL_FOLDERS, type ParameterRow } from '../render/parameterRow.ts';
import { VIEW_PARAMETERS, type ViewSettings } from './viewParameters.ts';

/** The panel's choice for an illuminant given by its CCT. */
const DAYLIGHT_CCT = 'daylight (CCT)';
/** The CCT slider's step. */
const CCT_STEP_K = 10;

/**
 * A lil-gui panel over every parameter the schema (VIEW_PARAMETERS) gives a control, grouped in
 * its folders. Sliders span each parameter's whole domain, so the panel cannot produce an invalid
 * setting and reaches every valid one. `onChange` receives the new settings.
 */
export function createControlPanel(initial: ViewSettings, onChange: (s: ViewSettings) => void, container?: HTMLElement): GUI {
  const state: Record<string, unknown> = { ...initial };
  /** The illuminant rows' two controls (a name, a CCT) write here, and `emit` joins them. */
  const illuminants = new Map<string, { name: string; cct: number }>();
  const emit = () => {
    const joined = [...illuminants].map(([key, { name, cct }]): [string, IlluminantSpec] => [
      key,
      name === DAYLIGHT_CCT ? { daylightCct: cct } : (name as IlluminantSpec),
    ]);
    onChange({ ...initial, ...(state as Partial<ViewSettings>), ...Object.fromEntries(joined) });
  };
  const gui = new GUI({ title: 'thin film', ...(container ? { container } : {}) });
  for (const folderName of PANEL_FOLDERS) {
    const folder = gui.addFolder(folderName);
    for (const row of VIEW_PARAMETERS.filter((r) => r.control?.folder === folderName)) addControl(folder, row, state, illuminants);
  }
  gui.onChange(emit);
  return gui;
}

function addControl(
  folder: GUI,
  row: ParameterRow<ViewSettings>,
  state: Record<string, unknown>,
  illuminants: Map<string, { name: string; cct: number }>,
): void {
  const control = row.control!;
  switch (control.kind) {
    case 'slider':
      folder.add(state, row.key, control.min, control.max, control.step).name(row.label);
      return;
    case 'choice':
      folder.add(state, row.key, [...control.choices]).name(row.label);
      return;
    case 'toggle':
      folder.add(state, row.key).name(row.label);
      return;
    case 'illuminant': {
      const spec = state[row.key] as IlluminantSpec;
      const pair = {
        name: typeof spec === 'object' ? DAYLIGHT_CCT : spec,
        // A named daylight starts the slider at its own CCT; E and the D65 table at D65's.
        cct: Math.round(daylightCctOf(spec) ?? daylightCctOf('D65')!),
      };
      illuminants.set(row.key, pair);
      folder.add(pair, 'name', [...NAMED_ILLUMINANTS, DAYLIGHT_CCT]).name(row.label);
      folder
        .add(pair, 'cct', DAYLIGHT_CCT_DOMAIN_K.min, DAYLIGHT_CCT_DOMAIN_K.max, CCT_STEP_K)
        .name(`daylight CCT (${DAYLIGHT_CCT_DOMAIN_K.unit})`);
      return;
    }
  }
}

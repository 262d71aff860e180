import { DEFAULT_VIEW_SETTINGS, type ViewSettings } from './viewParameters.ts';

/**
 * Where the demo page's default view differs from the schema's (DEFAULT_VIEW_SETTINGS, which the
 * element keeps): a bubble's life rather than the painted swirl. The film flows; a draught sweeps it
 * into a lopsided roll that turns with the draught's direction, once in 30 s, and evaporation
 * thins its top to black within the first half minute, then
 * it bursts and a new one follows; it is shown on black, where its colours are vivid
 * (docs/demo.md#the-default-view, where the numbers behind each value are). The float64 twin's
 * defaults (FLOW_PARAMETERS) stay still air, as its check against the analytic settled film needs.
 */
export const DEMO_VIEW_CHANGES = {
  field: 'flow',
  windMps: 0.05,
  windTurnDegS: 12,
  evaporationNmS: 20,
  seed: 3,
  env: 'none',
} as const satisfies Partial<ViewSettings>;

/** The demo page's default view: what its URL leaves out, read and written alike (settingsQuery's `base`). */
export const DEMO_VIEW_SETTINGS: ViewSettings = { ...DEFAULT_VIEW_SETTINGS, ...DEMO_VIEW_CHANGES };

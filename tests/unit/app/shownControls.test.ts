import { describe, expect, it } from 'vitest';
import { shownControls } from '../../../src/app/shownControls.ts';
import { FIELDS, FIELD_SETTINGS } from '../../../src/fields/fields.ts';
import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS, type ViewSettings } from '../../../src/settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../../../src/settings/demoView.ts';

const view = (changes: Partial<ViewSettings>): ViewSettings => ({ ...DEFAULT_VIEW_SETTINGS, ...changes });
const FLOW_FOLDER_KEYS = VIEW_PARAMETERS.filter((r) => r.control?.folder === 'flow').map((r) => r.key);
/** The rows a thickness field may hide: the fields' own settings (the swirl's speed and range, the flow folder's among them). */
const FIELD_OWN_KEYS = Object.keys(FIELD_SETTINGS);
const STACK = [{ n: 2.35, thicknessNm: 56.6 }] as const;

describe("the panel's shown controls", () => {
  it("with the swirl (the schema's default, the element's): its speed and range shown, the flow folder hidden, every other row shown", () => {
    const shown = shownControls(DEFAULT_VIEW_SETTINGS);
    expect(DEFAULT_VIEW_SETTINGS.field).toBe('swirl');
    expect(shown.rows).toMatchObject({ swirlSpeed: true, thicknessRangeNm: true, thicknessNm: true, field: true });
    for (const key of FLOW_FOLDER_KEYS) expect(shown.rows[key], key).toBe(false);
    expect(shown.folders).toEqual({ film: true, flow: false, 'light and colour': true, view: true });
    expect(FIELD_OWN_KEYS).toEqual(expect.arrayContaining(['thicknessRangeNm', 'swirlSpeed', ...FLOW_FOLDER_KEYS]));
    const others = VIEW_PARAMETERS.filter((r) => r.control && !FIELD_OWN_KEYS.includes(r.key));
    expect(others.length).toBeGreaterThan(10);
    for (const row of others) expect(shown.rows[row.key], row.key).toBe(true);
  });

  it('with the flow: the swirl speed and range hidden, the flow folder and each of its rows shown', () => {
    const shown = shownControls(view({ field: 'flow' }));
    expect(shown.rows).toMatchObject({ swirlSpeed: false, thicknessRangeNm: false, thicknessNm: true, field: true });
    expect(FLOW_FOLDER_KEYS).toEqual(expect.arrayContaining(['radiusMm', 'windMps', 'gridN', 'renew']));
    for (const key of FLOW_FOLDER_KEYS) expect(shown.rows[key], key).toBe(true);
    expect(shown.folders.flow).toBe(true);
  });

  it("the demo's default view (the flow): the swirl speed and range hidden, the flow folder shown", () => {
    const shown = shownControls(DEMO_VIEW_SETTINGS);
    expect(shown.rows).toMatchObject({
      swirlSpeed: false,
      thicknessRangeNm: false,
      thicknessNm: true,
      windMps: true,
      evaporationNmS: true,
    });
    expect(shown.folders.flow).toBe(true);
  });

  it('a uniform film shows its thickness alone; a drained film its range too, not the speed', () => {
    expect(shownControls(view({ field: 'uniform' })).rows).toMatchObject({ thicknessNm: true, thicknessRangeNm: false, swirlSpeed: false });
    expect(shownControls(view({ field: 'drainage' })).rows).toMatchObject({ thicknessNm: true, thicknessRangeNm: true, swirlSpeed: false });
    expect(shownControls(view({ field: 'drainage' })).folders.flow).toBe(false);
  });

  it("hides the film's own index while a stack is set, and shows it again without one", () => {
    for (const field of FIELDS) {
      expect(shownControls(view({ field, layers: STACK })).rows.nFilm, field).toBe(false);
      expect(shownControls(view({ field, layers: [] })).rows.nFilm, field).toBe(true);
    }
    expect(shownControls(view({ layers: STACK })).rows.nInside).toBe(true);
  });

  it("shows a medium's Cauchy or complex text field only while its kind is the one chosen", () => {
    expect(shownControls(view({ nFilm: 1.33, nInside: 1 })).texts).toEqual({ nFilm: null, nInside: null });
    expect(shownControls(view({ nFilm: 'water', nInside: 'Au' })).texts).toEqual({ nFilm: null, nInside: null });
    expect(shownControls(view({ nFilm: { cauchy: [1.45, 6000, 0] }, nInside: { complex: [2.6, 3.4] } })).texts).toEqual({
      nFilm: 'cauchy',
      nInside: 'complex',
    });
    // The kind chosen in the list counts where the panel says it: a text not yet taken stays shown.
    expect(shownControls(view({ nFilm: 'water', nInside: 1 }), { nFilm: 'cauchy', nInside: 'complex' }).texts).toEqual({
      nFilm: 'cauchy',
      nInside: 'complex',
    });
    expect(shownControls(view({ nFilm: { cauchy: [1.45, 6000, 0] } }), { nFilm: 'water' }).texts.nFilm).toBeNull();
    // A hidden row shows none of its text fields.
    expect(shownControls(view({ nFilm: { cauchy: [1.45, 6000, 0] }, layers: STACK })).texts.nFilm).toBeNull();
  });
});

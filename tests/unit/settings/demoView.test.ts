/** The demo page's default view: the schema's defaults with a few rows changed, read and written in the URL alike. */
import { describe, expect, it } from 'vitest';
import { DEMO_VIEW_CHANGES, DEMO_VIEW_SETTINGS } from '../../../src/settings/demoView.ts';
import { parseSettings, settingsToQuery } from '../../../src/settings/settingsQuery.ts';
import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS, type ViewSettings } from '../../../src/settings/viewParameters.ts';
import { DEFAULT_FLOW_PARAMETERS } from '../../../src/physics/filmDynamics/flowParameters.ts';
import { environmentKind } from '../../../src/environments/environments.ts';

describe("the demo's default view", () => {
  it('is the flowing film, in moving air and evaporating, on a dark surrounding; the rest is the schema’s default', () => {
    expect(DEMO_VIEW_SETTINGS.field).toBe('flow');
    expect(DEMO_VIEW_SETTINGS.windMps).toBeGreaterThan(0);
    expect(DEMO_VIEW_SETTINGS.evaporationNmS).toBeGreaterThan(0);
    expect(DEMO_VIEW_SETTINGS.seed).not.toBe(0);
    expect(environmentKind(DEMO_VIEW_SETTINGS.env)).toBe('none');
    const changed = Object.keys(DEMO_VIEW_SETTINGS).filter(
      (k) => DEMO_VIEW_SETTINGS[k as keyof ViewSettings] !== DEFAULT_VIEW_SETTINGS[k as keyof ViewSettings],
    );
    expect(changed.sort()).toEqual(Object.keys(DEMO_VIEW_CHANGES).sort());
  });

  it("leaves the element's default (the swirl) and the float64 twin's (still air, no evaporation, the uniform start) as they are", () => {
    expect(DEFAULT_VIEW_SETTINGS.field).toBe('swirl');
    expect([DEFAULT_FLOW_PARAMETERS.windMps, DEFAULT_FLOW_PARAMETERS.evaporationNmS, DEFAULT_FLOW_PARAMETERS.seed]).toEqual([0, 0, 0]);
  });

  it('holds values its rows accept: each written and read back is itself', () => {
    for (const row of VIEW_PARAMETERS) {
      const read = row.read(row.write(DEMO_VIEW_SETTINGS));
      expect(read, row.url).not.toBeNull();
      expect({ ...DEMO_VIEW_SETTINGS, ...read }, row.url).toEqual(DEMO_VIEW_SETTINGS);
    }
  });

  it('is what an empty query gives and what the URL leaves out; any other view round-trips over it', () => {
    expect(parseSettings('', DEMO_VIEW_SETTINGS)).toEqual({ settings: DEMO_VIEW_SETTINGS, errors: [], refusals: [] });
    expect(settingsToQuery(DEMO_VIEW_SETTINGS, DEMO_VIEW_SETTINGS)).toBe('');
    // The schema's default view (the element's), written over the demo's, names what differs.
    const swirl = settingsToQuery(DEFAULT_VIEW_SETTINGS, DEMO_VIEW_SETTINGS);
    expect(new URLSearchParams(swirl).get('field')).toBe('swirl');
    expect([...new URLSearchParams(swirl).keys()].sort()).toEqual(
      VIEW_PARAMETERS.filter((r) => r.key in DEMO_VIEW_CHANGES)
        .map((r) => r.url)
        .sort(),
    );
    for (const s of [DEFAULT_VIEW_SETTINGS, { ...DEMO_VIEW_SETTINGS, thicknessNm: 700, windMps: 0 }]) {
      expect(parseSettings(settingsToQuery(s, DEMO_VIEW_SETTINGS), DEMO_VIEW_SETTINGS).settings).toEqual(s);
    }
  });
});

/** The knobs a page may leave to its frame governor: `auto` by default, or a value given and kept exactly. */
import { describe, expect, it } from 'vitest';
import { FLOW_PARAMETERS } from '../../../src/physics/filmDynamics/flowParameters.ts';
import { parseSettings, settingsToQuery } from '../../../src/settings/settingsQuery.ts';
import { DEFAULT_VIEW_SETTINGS, PIXEL_RATIO_DOMAIN, VIEW_PARAMETERS, filmSettingsOf } from '../../../src/settings/viewParameters.ts';

const flowDefault = (key: string) => FLOW_PARAMETERS.find((r) => r.key === key)!.defaultValue;

describe('governed settings', () => {
  it('are auto unless given: a page leaves the grid, the simulation speed and the pixel ratio to its governor', () => {
    const { gridN, simSpeed, pixelRatio } = DEFAULT_VIEW_SETTINGS;
    expect({ gridN, simSpeed, pixelRatio }).toEqual({ gridN: 'auto', simSpeed: 'auto', pixelRatio: 'auto' });
    // Left at their defaults, none is written in the URL.
    expect(settingsToQuery(DEFAULT_VIEW_SETTINGS)).toBe('');
  });

  it('read a given value exactly, and `auto` as auto, and write both back (URL round trip)', () => {
    for (const query of [
      'grid=24',
      'grid=4',
      'grid=256',
      'simSpeed=0.5',
      'simSpeed=0',
      'pixelRatio=0.25',
      'pixelRatio=1.5',
      'pixelRatio=4',
    ]) {
      const { settings, errors } = parseSettings(`?${query}`);
      expect(errors, query).toEqual([]);
      expect(settingsToQuery(settings), query).toBe(query);
      expect(parseSettings(`?${settingsToQuery(settings)}`).settings, query).toEqual(settings);
    }
    const given = parseSettings('?grid=24&simSpeed=0.5&pixelRatio=1.5').settings;
    expect([given.gridN, given.simSpeed, given.pixelRatio]).toEqual([24, 0.5, 1.5]);
    const auto = parseSettings('?grid=auto&simSpeed=auto&pixelRatio=auto', given).settings;
    expect([auto.gridN, auto.simSpeed, auto.pixelRatio]).toEqual(['auto', 'auto', 'auto']);
  });

  it.each([
    ['pixelRatio', '0.2', 'pixelRatio="0.2" ignored: expected auto or a number in [0.25, 4]'],
    ['pixelRatio', '5', 'pixelRatio="5" ignored: expected auto or a number in [0.25, 4]'],
    ['pixelRatio', 'NaN', 'pixelRatio="NaN" ignored: expected auto or a number in [0.25, 4]'],
    ['pixelRatio', 'AUTO', 'pixelRatio="AUTO" ignored: expected auto or a number in [0.25, 4]'],
    ['grid', '257', 'grid="257" ignored: expected auto or an integer in [4, 256]'],
    ['grid', '24.5', 'grid="24.5" ignored: expected auto or an integer in [4, 256]'],
    ['simSpeed', '-0.1', 'simSpeed="-0.1" ignored: expected auto or a number in [0, 10]'],
  ])('refuse %s=%s, naming the parameter and its range, and keep the default', (name, value, refusal) => {
    const { settings, errors } = parseSettings(`?${name}=${value}`);
    expect(errors).toEqual([refusal]);
    expect(settings).toEqual(DEFAULT_VIEW_SETTINGS);
  });

  it('take their ranges from one place: the grid and speed from FLOW_PARAMETERS, the pixel ratio from its domain', () => {
    const control = (url: string) => VIEW_PARAMETERS.find((r) => r.url === url)!.control;
    const grid = FLOW_PARAMETERS.find((r) => r.key === 'gridN')!.domain;
    expect(control('grid')).toMatchObject({ kind: 'auto', min: grid.min, max: grid.max, step: 1 });
    expect(control('pixelRatio')).toMatchObject({ kind: 'auto', min: PIXEL_RATIO_DOMAIN.min, max: PIXEL_RATIO_DOMAIN.max });
  });

  it('in the panel: a toggle and a slider over the whole domain, which starts inside it', () => {
    const rows = VIEW_PARAMETERS.filter((r) => r.control?.kind === 'auto');
    expect(rows.map((r) => r.url)).toEqual(['simSpeed', 'grid', 'pixelRatio']);
    for (const row of rows) {
      const c = row.control as { min: number; max: number; step: number; start: number };
      expect(row.read(String(c.min)), row.url).not.toBeNull();
      expect(row.read(String(c.max)), row.url).not.toBeNull();
      expect(row.read(String(c.start)), row.url).not.toBeNull();
      expect(row.read(String(c.max + c.step)), row.url).toBeNull();
      expect(row.read(String(c.min - c.step)), row.url).toBeNull();
    }
  });

  it('draw, left to no governor, the simulation’s own grid and speed; given, exactly theirs', () => {
    const frozen = filmSettingsOf(DEFAULT_VIEW_SETTINGS);
    expect([frozen.gridN, frozen.simSpeed]).toEqual([flowDefault('gridN'), flowDefault('simSpeed')]);
    // The governor's choice fills what is auto, never what is given.
    expect(filmSettingsOf(DEFAULT_VIEW_SETTINGS, { gridN: 32 }).gridN).toBe(32);
    const given = parseSettings('?grid=24&simSpeed=0.5').settings;
    expect(filmSettingsOf(given, { gridN: 32, simSpeed: 1 })).toMatchObject({ gridN: 24, simSpeed: 0.5 });
    expect(Object.keys(filmSettingsOf(given))).not.toContain('pixelRatio');
  });
});

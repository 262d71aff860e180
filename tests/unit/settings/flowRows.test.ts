/** The flowing film's rows of the schema: their defaults, what they refuse and that the view's settings feed the simulation. */
import { describe, expect, it } from 'vitest';
import { flowParametersOf } from '../../../src/fields/flowField.ts';
import { parseSettings } from '../../../src/settings/settingsQuery.ts';
import { DEFAULT_VIEW_SETTINGS, filmSettingsOf } from '../../../src/settings/viewParameters.ts';

describe('flow rows', () => {
  it("default to the simulation's defaults (R 40 mm, Γ0 6.67e-8 mol/m², still air, the uniform start, N 128, real time), a new bubble after a burst", () => {
    // The grid and speed are the frame governor's (`auto`) on a page; a view drawn without it takes the simulation's.
    expect([DEFAULT_VIEW_SETTINGS.gridN, DEFAULT_VIEW_SETTINGS.simSpeed]).toEqual(['auto', 'auto']);
    const { radiusMm, surfactantMolM2, evaporationNmS, windMps, windTurnDegS, seed, simSpeed, gridN, renew } =
      filmSettingsOf(DEFAULT_VIEW_SETTINGS);
    expect({ radiusMm, surfactantMolM2, evaporationNmS, windMps, windTurnDegS, seed, simSpeed, gridN, renew }).toEqual({
      radiusMm: 40,
      surfactantMolM2: 6.67e-8,
      evaporationNmS: 0,
      windMps: 0,
      windTurnDegS: 0,
      seed: 0,
      simSpeed: 1,
      gridN: 128,
      renew: true,
    });
    // flow is a field to choose, not the default one.
    expect(DEFAULT_VIEW_SETTINGS.field).toBe('swirl');
  });

  it.each([
    ['radius', '9.99', 'radius="9.99" ignored: expected a number in [10, 100] mm'],
    ['surfactant', '2e-6', 'surfactant="2e-6" ignored: expected a number in [1e-8, 0.000001] mol/m²'],
    ['evaporation', '-1', 'evaporation="-1" ignored: expected a number in [0, 100] nm/s'],
    ['wind', '2.5', 'wind="2.5" ignored: expected a number in [0, 2] m/s'],
    ['windTurn', '361', 'windTurn="361" ignored: expected a number in [0, 360] degrees/s'],
    ['seed', '1.5', 'seed="1.5" ignored: expected an integer in [0, 2147483647]'],
    ['simSpeed', '11', 'simSpeed="11" ignored: expected auto or a number in [0, 10]'],
    ['grid', '300', 'grid="300" ignored: expected auto or an integer in [4, 256]'],
    ['grid', '3', 'grid="3" ignored: expected auto or an integer in [4, 256]'],
    ['grid', 'Auto', 'grid="Auto" ignored: expected auto or an integer in [4, 256]'],
    ['renew', 'yes', 'renew="yes" ignored: expected 0 or 1'],
  ])('refuses %s=%s, naming it and its range', (name, value, message) => {
    const { settings, errors } = parseSettings(`?field=flow&${name}=${value}`);
    expect(errors).toEqual([message]);
    expect(settings).toEqual({ ...DEFAULT_VIEW_SETTINGS, field: 'flow' });
  });

  it("gives the simulation the view's values, the mean thickness h̄ at least the model's 1 nm", () => {
    const { settings } = parseSettings(
      '?field=flow&radius=25&surfactant=2e-7&evaporation=3&wind=0.5&windTurn=30&seed=42&grid=32&thickness=0',
    );
    expect(flowParametersOf(filmSettingsOf(settings))).toEqual({
      radiusMm: 25,
      thicknessNm: 1,
      surfactantMolM2: 2e-7,
      evaporationNmS: 3,
      windMps: 0.5,
      windTurnDegS: 30,
      seed: 42,
      ruptureThicknessNm: 10,
      rimSpeedFactor: 1,
      gridN: 32,
      simSpeed: 1,
    });
  });
});

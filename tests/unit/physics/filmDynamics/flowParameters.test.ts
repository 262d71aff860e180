/**
 * The flow parameters and the numbers of eq. (17). Expected values: the defaults and ranges the
 * model is specified with, the numbers recomputed here from the published constants, and the
 * stationary film the project's physics notes work through (R = 4 cm, h̄ = 800 nm,
 * Γ0 = 6.67e-8 mol/m²: a ≈ 0.95, bottom/top ≈ 6.6).
 */
import { describe, expect, it } from 'vitest';
import { flowNumbers, surfaceTensionNM, taylorCulickSpeedMps } from '../../../../src/physics/filmDynamics/flowNumbers.ts';
import { DEFAULT_FLOW_PARAMETERS, FLOW_PARAMETERS, validateFlowParameters } from '../../../../src/physics/filmDynamics/flowParameters.ts';
import { createFilmSimulation } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { ParameterError } from '../../../../src/input/validate.ts';
import { ALGEBRAIC_TOL, FEW_OPERATIONS_TOL, printedValueTol } from '../../../tolerances.ts';
import { stationaryExponent } from './flowTestHelpers.ts';

describe('flow parameters', () => {
  it('default to the specified values', () => {
    expect(DEFAULT_FLOW_PARAMETERS).toEqual({
      radiusMm: 40,
      thicknessNm: 550,
      surfactantMolM2: 6.67e-8,
      evaporationNmS: 0,
      windMps: 0,
      windTurnDegS: 0,
      seed: 0,
      ruptureThicknessNm: 10,
      rimSpeedFactor: 1,
      gridN: 128,
      simSpeed: 1,
    });
  });
  it('accept both ends of every range', () => {
    for (const r of FLOW_PARAMETERS) {
      expect(validateFlowParameters({ [r.key]: r.domain.min })[r.key]).toBe(r.domain.min);
      expect(validateFlowParameters({ [r.key]: r.domain.max })[r.key]).toBe(r.domain.max);
    }
  });
  for (const r of FLOW_PARAMETERS) {
    const span = r.domain.max - r.domain.min;
    const bad: unknown[] = [r.domain.min - span * 1e-3 - 1e-12, r.domain.max + span * 1e-3, Number.NaN, Infinity, '5', null];
    if (r.integer) bad.push(r.domain.min + 0.5);
    it(`refuse a bad ${r.key}, naming it and its range`, () => {
      for (const value of bad) {
        const attempt = () => validateFlowParameters({ [r.key]: value });
        expect(attempt).toThrow(ParameterError);
        expect(attempt).toThrow(new RegExp(`^${r.key}: .* expected (an integer|a number) in \\[${r.domain.min}, ${r.domain.max}\\]`));
        expect(() => createFilmSimulation({ [r.key]: value })).toThrow(ParameterError);
      }
    });
  }
  it('refuse an unknown parameter by name', () => {
    expect(() => validateFlowParameters({ radius: 40 })).toThrow(/^radius: not a flow parameter/);
  });
});

describe('the numbers of eq. (17)', () => {
  const p = validateFlowParameters({ radiusMm: 40, thicknessNm: 800, surfactantMolM2: 6.67e-8, evaporationNmS: 10, windMps: 1.5 });
  const n = flowNumbers(p);
  const rt = 8.3144598 * 298.15;
  it('M = Γ0R̄T/(ρη0U²), Cr = ρa√(νaR)/(ρη0√U), g = GR/U² with η0 = h̄/2 and U = 1 m/s', () => {
    expect(Math.abs(n.marangoni / ((6.67e-8 * rt) / (997 * 400e-9)) - 1)).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(n.airFriction / ((1.184 * Math.sqrt(1.562e-5 * 0.04)) / (997 * 400e-9)) - 1)).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(n.gravity - 9.8 * 0.04)).toBeLessThan(ALGEBRAIC_TOL);
  });
  it('g/M is the stationary exponent a ≈ 0.95 of the worked example, bottom/top = e^(2a) ≈ 6.6', () => {
    const a = n.gravity / n.marangoni;
    expect(Math.abs(a / stationaryExponent(40, 800, 6.67e-8) - 1)).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(a - 0.95)).toBeLessThan(printedValueTol(2));
    expect(Math.abs(Math.exp(2 * a) - 6.6)).toBeLessThan(printedValueTol(1));
  });
  it('evaporation of 10 nm/s of an 800 nm film is 1/80 of η per second, R/U = 0.04 s per unit time', () => {
    expect(Math.abs(n.evaporation - (10 / 800) * 0.04)).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(n.timeScaleS - 0.04)).toBeLessThan(FEW_OPERATIONS_TOL);
  });
  it('rupture at the rupture thickness over the mean, and where γ_a − R̄TΓ0Γ reaches 0', () => {
    expect(Math.abs(n.ruptureEta - 10 / 800)).toBeLessThan(FEW_OPERATIONS_TOL);
    expect(Math.abs(surfaceTensionNM(p, n.ruptureGamma))).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(surfaceTensionNM(p, 1) - (0.07275 - rt * 6.67e-8))).toBeLessThan(FEW_OPERATIONS_TOL);
  });
  it('Taylor–Culick: √(2γ/(ρh)) is 7.1 m/s at γ = 0.025 N/m, h = 1 µm and 22 m/s at 100 nm', () => {
    expect(Math.abs(taylorCulickSpeedMps(0.025, 1e-6) - 7.08)).toBeLessThan(printedValueTol(2));
    expect(Math.abs(taylorCulickSpeedMps(0.025, 1e-7) - 22.4)).toBeLessThan(printedValueTol(1));
  });
});

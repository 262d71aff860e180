import { FILM_STACK_DOMAIN } from '../filmReflectance.ts';
import { ParameterError, describeValue, expectedNumber, isInDomain, type NumberDomain } from '../../input/validate.ts';

/**
 * Every parameter of the film-flow simulation in one table: its key, its domain, its default and
 * whether it must be an integer. Validation and the settings schema (src/settings/filmParameters.ts,
 * whence the names, labels and flags of the page and the command line) derive from this table;
 * nothing else writes a range or a default.
 */
export interface FlowParameterRow {
  readonly key: FlowParameterKey;
  readonly domain: NumberDomain;
  readonly defaultValue: number;
  readonly integer: boolean;
}

export type FlowParameterKey =
  | 'radiusMm'
  | 'thicknessNm'
  | 'surfactantMolM2'
  | 'evaporationNmS'
  | 'windMps'
  | 'windTurnDegS'
  | 'seed'
  | 'ruptureThicknessNm'
  | 'rimSpeedFactor'
  | 'gridN'
  | 'simSpeed';

export type FlowParameters = Readonly<Record<FlowParameterKey, number>>;

/**
 * The mean full thickness shares the film stack's unit and upper end; its lower end is 1 nm, not
 * 0, because the model's numbers divide by the initial half-thickness η0 (docs/flow.md#parameters).
 * Its default, 550 nm, is the bubble view's default thickness.
 */
const THICKNESS_DOMAIN: NumberDomain = { min: 1, max: FILM_STACK_DOMAIN.thicknessNm.max, unit: FILM_STACK_DOMAIN.thicknessNm.unit };

const row = (key: FlowParameterKey, domain: NumberDomain, defaultValue: number, integer = false): FlowParameterRow => ({
  key,
  domain,
  defaultValue,
  integer,
});

export const FLOW_PARAMETERS: readonly FlowParameterRow[] = [
  row('radiusMm', { min: 10, max: 100, unit: 'mm' }, 40),
  row('thicknessNm', THICKNESS_DOMAIN, 550),
  // 6.67e-8 mol/m²: the surface excess of a soap solution near its critical micelle concentration.
  row('surfactantMolM2', { min: 1e-8, max: 1e-6, unit: 'mol/m²' }, 6.67e-8),
  row('evaporationNmS', { min: 0, max: 100, unit: 'nm/s' }, 0),
  row('windMps', { min: 0, max: 2, unit: 'm/s' }, 0),
  // Up to a turn a second: a draught that veers faster than the film settles (~1 s) only stirs it.
  row('windTurnDegS', { min: 0, max: 360, unit: 'degrees/s' }, 0),
  row('seed', { min: 0, max: 2_147_483_647, unit: '' }, 0, true),
  row('ruptureThicknessNm', { min: 0, max: 100, unit: 'nm' }, 10),
  row('rimSpeedFactor', { min: 0.01, max: 1, unit: '' }, 1),
  row('gridN', { min: 4, max: 256, unit: '' }, 128, true),
  row('simSpeed', { min: 0, max: 10, unit: '' }, 1),
];

export const DEFAULT_FLOW_PARAMETERS: FlowParameters = Object.fromEntries(
  FLOW_PARAMETERS.map((r) => [r.key, r.defaultValue]),
) as FlowParameters;

/** What a row accepts, as every message states it. */
export const expectedFlowValue = (r: FlowParameterRow): string =>
  r.integer ? `an integer in [${r.domain.min}, ${r.domain.max}]` : expectedNumber(r.domain);

export const acceptsFlowValue = (r: FlowParameterRow, value: unknown): value is number =>
  isInDomain(value, r.domain) && (!r.integer || Number.isInteger(value));

/**
 * The full parameter set: the defaults overridden by `given`, every value checked. A value outside
 * its row's domain (NaN, ±Infinity, a fraction where an integer is due, an unknown key) throws a
 * ParameterError naming the parameter and its range, before anything is computed.
 */
export function validateFlowParameters(given: Partial<Record<string, unknown>> = {}): FlowParameters {
  for (const key of Object.keys(given)) {
    if (!FLOW_PARAMETERS.some((r) => r.key === key)) {
      throw new ParameterError(key, `${key}: not a flow parameter; expected one of ${FLOW_PARAMETERS.map((r) => r.key).join(', ')}`);
    }
  }
  const values = { ...DEFAULT_FLOW_PARAMETERS } as Record<FlowParameterKey, number>;
  for (const r of FLOW_PARAMETERS) {
    const value = given[r.key];
    if (value === undefined) continue;
    if (!acceptsFlowValue(r, value)) {
      throw new ParameterError(r.key, `${r.key}: ${describeValue(value)} is not allowed; expected ${expectedFlowValue(r)}`);
    }
    values[r.key] = value;
  }
  return values;
}

import type { FlowNumbers } from './flowNumbers.ts';
import type { FlowParameters } from './flowParameters.ts';
import { WIND_SURFACE_FACTOR } from './timeStep.ts';

/**
 * The wind's direction at film time t (s, ≥ 0): it blows along (cos φ, sin φ, 0), φ = turn·t, the
 * direction turning about the vertical +z at windTurnDegS degrees per second (counter-clockwise
 * seen from above: +x towards +y); φ = 0, along +x, when the rate is 0. A stand-in for a room's
 * veering draught, not a model of its air (docs/flow.md#the-model). The angle is reduced to a turn
 * in degrees before the conversion to radians, so a long film keeps its direction's precision.
 */
export const windAngleRad = (p: Pick<FlowParameters, 'windTurnDegS'>, seconds: number): number =>
  (((p.windTurnDegS * seconds) % 360) * Math.PI) / 180;

/**
 * The air at the surface as the x and y components of WIND_SURFACE_FACTOR × the wind (in U) at
 * the direction of angle φ (windAngleRad): u_air,e = (x, y)·(n_x, n_y) at an edge of normal n.
 */
export const surfaceWind = (numbers: Pick<FlowNumbers, 'wind'>, angleRad: number): [number, number] => [
  WIND_SURFACE_FACTOR * numbers.wind * Math.cos(angleRad),
  WIND_SURFACE_FACTOR * numbers.wind * Math.sin(angleRad),
];

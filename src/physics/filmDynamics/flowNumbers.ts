import {
  AIR_DENSITY_KG_M3,
  AIR_KINEMATIC_VISCOSITY_M2_S,
  GAS_CONSTANT_TIMES_TEMPERATURE,
  GRAVITY_M_S2,
  PURE_SURFACE_TENSION_N_M,
  VELOCITY_SCALE_M_S,
  WATER_DENSITY_KG_M3,
} from './flowConstants.ts';
import type { FlowParameters } from './flowParameters.ts';

/**
 * The dimensionless numbers of eq. (17) for one parameter set. Lengths are in bubble radii R,
 * velocities in U, time in R/U, the half-thickness η in η0 = h̄/2 and the surfactant
 * concentration Γ in Γ0 (docs/flow.md#the-model).
 */
export interface FlowNumbers {
  /** η0, the initial uniform half-thickness (m). */
  readonly halfThicknessM: number;
  /** R (m). */
  readonly radiusM: number;
  /** Seconds per unit of dimensionless time, R/U. */
  readonly timeScaleS: number;
  /** M = Γ0 R̄T/(ρ η0 U²): the Marangoni number (no factor 1/3, docs/flow.md#the-factor-13). */
  readonly marangoni: number;
  /** Cr = ρ_a √(ν_a R)/(ρ η0 √U): the air-friction number. */
  readonly airFriction: number;
  /** g = G R/U². */
  readonly gravity: number;
  /** e: the loss of η per unit time by evaporation (η0 per R/U). */
  readonly evaporation: number;
  /** The wind's speed in U (blowing along +x at t = 0, its direction turning about +z: windDirection.ts). */
  readonly wind: number;
  /** η below which the film ruptures: rupture thickness / mean thickness. */
  readonly ruptureEta: number;
  /** Γ at which γ = γ_a − R̄TΓ0Γ falls to 0: γ_a/(R̄TΓ0). */
  readonly ruptureGamma: number;
}

export function flowNumbers(p: FlowParameters): FlowNumbers {
  const radiusM = p.radiusMm * 1e-3;
  const halfThicknessM = (p.thicknessNm * 1e-9) / 2;
  const u = VELOCITY_SCALE_M_S;
  const densityEta = WATER_DENSITY_KG_M3 * halfThicknessM;
  return {
    halfThicknessM,
    radiusM,
    timeScaleS: radiusM / u,
    marangoni: (p.surfactantMolM2 * GAS_CONSTANT_TIMES_TEMPERATURE) / (densityEta * u * u),
    airFriction: (AIR_DENSITY_KG_M3 * Math.sqrt(AIR_KINEMATIC_VISCOSITY_M2_S * radiusM)) / (densityEta * Math.sqrt(u)),
    gravity: (GRAVITY_M_S2 * radiusM) / (u * u),
    evaporation: ((p.evaporationNmS * 1e-9) / 2 / halfThicknessM) * (radiusM / u),
    wind: p.windMps / u,
    ruptureEta: p.ruptureThicknessNm / p.thicknessNm,
    ruptureGamma: PURE_SURFACE_TENSION_N_M / (GAS_CONSTANT_TIMES_TEMPERATURE * p.surfactantMolM2),
  };
}

/** γ = γ_a − R̄TΓ (N/m) for a dimensionless Γ, never below 0. */
export const surfaceTensionNM = (p: FlowParameters, gamma: number): number =>
  Math.max(0, PURE_SURFACE_TENSION_N_M - GAS_CONSTANT_TIMES_TEMPERATURE * p.surfactantMolM2 * gamma);

/** The Taylor–Culick speed √(2γ/(ρh)) (m/s) of a rim entering film of full thickness h (m). */
export const taylorCulickSpeedMps = (surfaceTension: number, fullThicknessM: number): number =>
  Math.sqrt((2 * surfaceTension) / (WATER_DENSITY_KG_M3 * fullThicknessM));

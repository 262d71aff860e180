/**
 * The physical constants of the film-flow model (Huang et al. 2020, eq. 17 and its Table of
 * constants), SI units. docs/flow.md#the-model says where each enters.
 */

/** γ_a, the surface tension of the surfactant-free water surface (N/m). */
export const PURE_SURFACE_TENSION_N_M = 0.07275;
/** R̄, the molar gas constant (J/(mol K)). */
export const GAS_CONSTANT_J_MOL_K = 8.3144598;
/** T, room temperature (K). */
export const TEMPERATURE_K = 298.15;
/** ρ, the density of the film's water (kg/m³). */
export const WATER_DENSITY_KG_M3 = 997;
/** ρ_a, the density of air (kg/m³). */
export const AIR_DENSITY_KG_M3 = 1.184;
/** ν_a, the kinematic viscosity of air (m²/s). */
export const AIR_KINEMATIC_VISCOSITY_M2_S = 1.562e-5;
/** G, the acceleration of gravity (m/s²). */
export const GRAVITY_M_S2 = 9.8;
/** U, the velocity scale of the dimensionless model (m/s). */
export const VELOCITY_SCALE_M_S = 1;
/** R̄T (J/mol): the surface pressure per unit surfactant concentration, γ = γ_a − R̄TΓ. */
export const GAS_CONSTANT_TIMES_TEMPERATURE = GAS_CONSTANT_J_MOL_K * TEMPERATURE_K;

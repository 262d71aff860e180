import { paddedSampler } from './cubeSphereSampler.ts';
import { type FilmSimulation, paddedEta } from './filmSimulation.ts';

/** ∫ q dA over the unit sphere for a cell field (η: the film's volume in 2η0R² units; Γ: its surfactant in Γ0R²). */
export function sphereIntegral(sim: FilmSimulation, field: Float64Array): number {
  let sum = 0;
  for (let c = 0; c < field.length; c++) sum += sim.grid.area[c]! * field[c]!;
  return sum;
}

/** The mean full thickness over the sphere (nm), holes counting as 0. */
export const meanThicknessNm = (sim: FilmSimulation): number =>
  (sim.parameters.thicknessNm * sphereIntegral(sim, sim.state.eta)) / (4 * Math.PI);

/** The thinnest and thickest cell (full thickness, nm). */
export function thicknessRangeNm(sim: FilmSimulation): { minNm: number; maxNm: number } {
  let min = Infinity;
  let max = -Infinity;
  for (const eta of sim.state.eta) {
    min = Math.min(min, eta);
    max = Math.max(max, eta);
  }
  return { minNm: min * sim.parameters.thicknessNm, maxNm: max * sim.parameters.thicknessNm };
}

/**
 * h(direction): the full thickness (nm) at a direction (x, y, z), any non-zero vector, bilinear
 * between cell centres, for rendering on the CPU. The sampler reads the state as it is when created.
 */
export function thicknessSampler(sim: FilmSimulation): (x: number, y: number, z: number) => number {
  const padded = paddedEta(sim);
  const sample = paddedSampler(sim.halo, 1);
  const out = new Float64Array(1);
  const scale = sim.parameters.thicknessNm;
  return (x, y, z) => {
    sample(padded, x, y, z, out);
    return scale * out[0]!;
  };
}

/** The polar angles of the profile: 0, 5, …, 180 degrees from the top. */
export const PROFILE_THETA_DEG: readonly number[] = Array.from({ length: 37 }, (_, k) => 5 * k);
/** Azimuths averaged at each polar angle. */
const PROFILE_AZIMUTHS = 72;

/** The azimuthal mean of the full thickness (nm) at each of PROFILE_THETA_DEG (θ from the top, +z). */
export function thicknessProfileNm(sim: FilmSimulation): number[] {
  const h = thicknessSampler(sim);
  return PROFILE_THETA_DEG.map((thetaDeg) => {
    const theta = (thetaDeg * Math.PI) / 180;
    let sum = 0;
    for (let k = 0; k < PROFILE_AZIMUTHS; k++) {
      const phi = (2 * Math.PI * (k + 0.5)) / PROFILE_AZIMUTHS;
      sum += h(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
    }
    return sum / PROFILE_AZIMUTHS;
  });
}

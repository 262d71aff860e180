import { type CubeSphereHalo, padField, paddedSampler } from './cubeSphereSampler.ts';
import { type FilmHole, HOLE_RAYS, MAX_HOLES, insideHole, newHole, pointOnRay } from './filmHoles.ts';
import { type FlowNumbers, surfaceTensionNM, taylorCulickSpeedMps } from './flowNumbers.ts';
import type { FlowParameters } from './flowParameters.ts';
import { VELOCITY_SCALE_M_S } from './flowConstants.ts';

/** The thinnest film a rim speed is computed for (nm): ahead of a rim there is film, and √(1/h) stays finite. */
const RIM_THICKNESS_FLOOR_NM = 1;
/** How far ahead of a rim its film is sampled, in cells (π/(2n) radians each): far enough that the bilinear taps miss the cells already emptied. */
const RIM_LEAD_CELLS = 1.5;
/** That lead in radians on a grid of n × n cells per face. */
export const rimLeadRad = (n: number): number => (RIM_LEAD_CELLS * Math.PI) / (2 * n);

export interface RuptureInputs {
  readonly halo: CubeSphereHalo;
  readonly parameters: FlowParameters;
  readonly numbers: FlowNumbers;
  readonly eta: Float64Array;
  readonly gamma: Float64Array;
  readonly intact: Uint8Array;
  readonly holes: FilmHole[];
}

/** Whether cell c of an intact film ruptures now: γ = γ_a − R̄TΓ would reach 0, or the film is at or below the rupture thickness. */
const rupturesHere = (numbers: FlowNumbers, eta: number, gamma: number): boolean =>
  eta <= numbers.ruptureEta || gamma >= numbers.ruptureGamma;

/** A hole at a direction (a puncture, or where the film gave way): a new tracked hole, if there is room. */
export function openHole(holes: FilmHole[], x: number, y: number, z: number): void {
  if (holes.length < MAX_HOLES) holes.push(newHole(x, y, z));
}

/**
 * Rupture and Taylor–Culick bursting (GPU pass 8): cells that give way open holes; every
 * rim ray advances by Δt·V, V = rimSpeedFactor·√(2γ/(ρh)) with h the full thickness and γ the
 * tension of the film a little ahead of the rim; cells the rims have passed lose their film
 * (η = Γ = 0, no longer intact). docs/flow.md#rupture-and-bursting.
 */
export function ruptureFilm(inputs: RuptureInputs, dt: number): void {
  const { halo, numbers, eta, gamma, intact, holes } = inputs;
  const { grid } = halo;
  const { center } = grid;
  for (let c = 0; c < grid.cellCount; c++) {
    if (intact[c] === 0 || !rupturesHere(numbers, eta[c]!, gamma[c]!)) continue;
    const [x, y, z] = [center[3 * c]!, center[3 * c + 1]!, center[3 * c + 2]!];
    if (!holes.some((h) => insideHole(h, x, y, z))) openHole(holes, x, y, z);
    removeFilm(c, eta, gamma, intact);
  }
  if (holes.length === 0) return;
  growRims(inputs, dt);
  for (let c = 0; c < grid.cellCount; c++) {
    if (intact[c] === 0) continue;
    const [x, y, z] = [center[3 * c]!, center[3 * c + 1]!, center[3 * c + 2]!];
    if (holes.some((h) => insideHole(h, x, y, z))) removeFilm(c, eta, gamma, intact);
  }
}

function removeFilm(c: number, eta: Float64Array, gamma: Float64Array, intact: Uint8Array): void {
  eta[c] = 0;
  gamma[c] = 0;
  intact[c] = 0;
}

/** The thinnest film (nm) a rim's speed is computed for: the rupture thickness, at least RIM_THICKNESS_FLOOR_NM. */
export const rimThicknessFloorNm = (p: FlowParameters): number => Math.max(p.ruptureThicknessNm, RIM_THICKNESS_FLOOR_NM);

function growRims(inputs: RuptureInputs, dt: number): void {
  const { halo, parameters, numbers, eta, gamma, holes } = inputs;
  const sample = paddedSampler(halo, 1);
  const paddedEta = padField(halo, eta, 1);
  const paddedGamma = padField(halo, gamma, 1);
  const lead = rimLeadRad(halo.grid.n);
  const point = new Float64Array(3);
  const value = new Float64Array(1);
  const floorM = rimThicknessFloorNm(parameters) * 1e-9;
  for (const hole of holes) {
    for (let k = 0; k < HOLE_RAYS; k++) {
      const r = hole.radius[k]!;
      if (r >= Math.PI) continue;
      pointOnRay(hole, (2 * Math.PI * k) / HOLE_RAYS, Math.min(Math.PI, r + lead), point);
      sample(paddedEta, point[0]!, point[1]!, point[2]!, value);
      const thicknessM = Math.max(floorM, 2 * numbers.halfThicknessM * value[0]!);
      sample(paddedGamma, point[0]!, point[1]!, point[2]!, value);
      const speed =
        (parameters.rimSpeedFactor * taylorCulickSpeedMps(surfaceTensionNM(parameters, value[0]!), thicknessM)) / VELOCITY_SCALE_M_S;
      hole.radius[k] = Math.min(Math.PI, r + speed * dt);
    }
  }
}

import type { CubeSphereGrid } from './cubeSphereGrid.ts';
import type { FlowNumbers } from './flowNumbers.ts';
import { logarithmicMean } from './logarithmicMean.ts';

/** A function writing the bilinear value of a padded 3-component field at a direction into out. */
export type VectorSampler = (padded: Float64Array, x: number, y: number, z: number, out: Float64Array) => void;

export interface EdgePrediction {
  /** u*: the edge-normal velocity after advection, gravity and air friction, before the Marangoni term. */
  readonly predicted: Float64Array;
  /** c_e = M/(η_e/Δt + Cr): the edge velocity is u* − c_e ∂Γ/∂n once Γ is known. */
  readonly marangoniCoefficient: Float64Array;
}

/** What the prediction reads of the film: its cell velocities (padded too, sampled by `sample`), η, intact, and the air's normal velocity per edge. */
export interface PredictionInputs {
  readonly cellVelocity: Float64Array;
  readonly paddedCellVelocity: Float64Array;
  readonly sample: VectorSampler;
  readonly eta: Float64Array;
  readonly intact: Uint8Array;
  readonly windAlongNormal: Float64Array;
}

/**
 * The semi-Lagrangian advection at edge e between cells ca and cb: the velocity at the midpoint,
 * traced back along the great circle for Δt, sampled there and parallel-transported to the edge,
 * along the edge's normal. `b` is scratch for the sample.
 */
function advectedAlongNormal(
  grid: CubeSphereGrid,
  dt: number,
  inputs: PredictionInputs,
  [e, ca, cb]: [number, number, number],
  b: Float64Array,
): number {
  const { edgeMid, edgeNormal } = grid;
  const { cellVelocity, paddedCellVelocity, sample } = inputs;
  const mx = edgeMid[3 * e]!;
  const my = edgeMid[3 * e + 1]!;
  const mz = edgeMid[3 * e + 2]!;
  const nx = edgeNormal[3 * e]!;
  const ny = edgeNormal[3 * e + 1]!;
  const nz = edgeNormal[3 * e + 2]!;
  // The velocity at the midpoint: the mean of the two cells', in the tangent plane there.
  let wx = 0.5 * (cellVelocity[3 * ca]! + cellVelocity[3 * cb]!);
  let wy = 0.5 * (cellVelocity[3 * ca + 1]! + cellVelocity[3 * cb + 1]!);
  let wz = 0.5 * (cellVelocity[3 * ca + 2]! + cellVelocity[3 * cb + 2]!);
  const radial = wx * mx + wy * my + wz * mz;
  wx -= radial * mx;
  wy -= radial * my;
  wz -= radial * mz;
  const speed = Math.hypot(wx, wy, wz);
  if (!(speed * dt > 0)) return wx * nx + wy * ny + wz * nz;
  const s = speed * dt;
  const tx = wx / speed;
  const ty = wy / speed;
  const tz = wz / speed;
  const cs = Math.cos(s);
  const sn = Math.sin(s);
  sample(paddedCellVelocity, cs * mx - sn * tx, cs * my - sn * ty, cs * mz - sn * tz, b);
  // Parallel transport along the great circle: the component along the path (τ at the
  // departure point) becomes the component along t̂ here; the one along k = m × t̂ is kept.
  const kx = my * tz - mz * ty;
  const ky = mz * tx - mx * tz;
  const kz = mx * ty - my * tx;
  const along = b[0]! * (sn * mx + cs * tx) + b[1]! * (sn * my + cs * ty) + b[2]! * (sn * mz + cs * tz);
  const across = b[0]! * kx + b[1]! * ky + b[2]! * kz;
  return along * (tx * nx + ty * ny + tz * nz) + across * (kx * nx + ky * ny + kz * nz);
}

/**
 * Advection and the semi-implicit force step of eq. (17) at each edge (GPU pass 3). The velocity
 * is traced back along the great circle for Δt (semi-Lagrangian), sampled there and
 * parallel-transported to the edge (advectedAlongNormal); then
 *   u_e = (η_e u_adv/Δt + η_e g_e + Cr u_air − M ∂Γ/∂n) / (η_e/Δt + Cr),
 * the paper's u = (u_adv/Δt + f)/(1/Δt + Cr/η) multiplied through by η, so a vanishing film follows
 * the air instead of dividing by zero. η_e is the logarithmic mean of the two cells' η and
 * g_e = −g ∂(cos θ)/∂n gravity as the gradient of its potential: then η_e g_e = M ∂Γ/∂n holds
 * exactly on every edge of a film with Γ = η ∝ e^(−a cos θ), and the stationary film is exactly
 * at rest (well balanced). The Marangoni term waits for the surfactant solve; this pass returns u*
 * and c_e. Edges beside a ruptured cell are closed (both 0). docs/flow.md#the-step.
 */
export function predictEdgeVelocity(
  grid: CubeSphereGrid,
  numbers: FlowNumbers,
  dt: number,
  inputs: PredictionInputs,
  out: EdgePrediction,
): void {
  const { edgeA, edgeB, edgeDistance, center } = grid;
  const { eta, intact, windAlongNormal } = inputs;
  const { airFriction, gravity, marangoni } = numbers;
  const b = new Float64Array(3);
  for (let e = 0; e < grid.edgeCount; e++) {
    const ca = edgeA[e]!;
    const cb = edgeB[e]!;
    if (intact[ca] === 0 || intact[cb] === 0) {
      out.predicted[e] = 0;
      out.marangoniCoefficient[e] = 0;
      continue;
    }
    const advected = advectedAlongNormal(grid, dt, inputs, [e, ca, cb], b);
    const etaEdge = logarithmicMean(eta[ca]!, eta[cb]!);
    const gravityAlongNormal = (-gravity * (center[3 * cb + 2]! - center[3 * ca + 2]!)) / edgeDistance[e]!;
    const denominator = etaEdge / dt + airFriction;
    out.predicted[e] = ((etaEdge * advected) / dt + etaEdge * gravityAlongNormal + airFriction * windAlongNormal[e]!) / denominator;
    out.marangoniCoefficient[e] = marangoni / denominator;
  }
}

import type { CubeSphereGrid } from './cubeSphereGrid.ts';

export interface TransportWork {
  /** Per cell: the fraction of its outflow allowed (≤ 1), so no cell sends more than it holds. */
  readonly limiter: Float64Array;
  readonly etaFlux: Float64Array;
  readonly gammaFlux: Float64Array;
}

export const transportWork = (grid: CubeSphereGrid): TransportWork => ({
  limiter: new Float64Array(grid.cellCount),
  etaFlux: new Float64Array(grid.edgeCount),
  gammaFlux: new Float64Array(grid.edgeCount),
});

/**
 * Dη/Dt = −η∇·u and DΓ/Dt = −Γ∇·u of eq. (17) in conservation form, ∂q/∂t + ∇·(qu) = 0, by
 * first-order upwind finite volumes (GPU pass 6: limiter, edge fluxes, cell update): each edge carries Δt L_e u_e q_upwind from
 * one cell to the other, the same number leaving one and entering the other, so ∫η dA and ∫Γ dA
 * change only by rounding. A cell whose outflow in one step would exceed its content has all its
 * outflows scaled down to exactly its content (the same factor for η and Γ, so Γ/η is carried
 * unchanged), which keeps η ≥ 0 and Γ ≥ 0 for any Δt. docs/flow.md#conservation.
 */
export function transportFilm(
  grid: CubeSphereGrid,
  dt: number,
  edgeVelocity: Float64Array,
  eta: Float64Array,
  gamma: Float64Array,
  work: TransportWork,
): void {
  const { area, cellEdge, cellEdgeSign, edgeA, edgeB, edgeLength } = grid;
  const { limiter, etaFlux, gammaFlux } = work;
  for (let c = 0; c < grid.cellCount; c++) {
    let outflow = 0;
    for (let s = 0; s < 4; s++) {
      const e = cellEdge[4 * c + s]!;
      outflow += edgeLength[e]! * Math.max(0, cellEdgeSign[4 * c + s]! * edgeVelocity[e]!);
    }
    outflow *= dt;
    limiter[c] = outflow > area[c]! ? area[c]! / outflow : 1;
  }
  for (let e = 0; e < grid.edgeCount; e++) {
    const u = edgeVelocity[e]!;
    const upwind = u >= 0 ? edgeA[e]! : edgeB[e]!;
    const volume = dt * edgeLength[e]! * u * limiter[upwind]!;
    etaFlux[e] = volume * eta[upwind]!;
    gammaFlux[e] = volume * gamma[upwind]!;
  }
  for (let c = 0; c < grid.cellCount; c++) {
    let etaOut = 0;
    let gammaOut = 0;
    for (let s = 0; s < 4; s++) {
      const e = cellEdge[4 * c + s]!;
      etaOut += cellEdgeSign[4 * c + s]! * etaFlux[e]!;
      gammaOut += cellEdgeSign[4 * c + s]! * gammaFlux[e]!;
    }
    // max(0, ·) only absorbs rounding: the limiter already bounds the outflow by the content.
    eta[c] = Math.max(0, eta[c]! - etaOut / area[c]!);
    gamma[c] = Math.max(0, gamma[c]! - gammaOut / area[c]!);
  }
}

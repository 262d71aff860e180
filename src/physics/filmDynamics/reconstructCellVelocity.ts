import type { CubeSphereGrid } from './cubeSphereGrid.ts';

/**
 * The tangent velocity vector at each cell centre from the normal velocities of its 4 edges
 * (Perot's reconstruction: u_c = (1/A_c) Σ_e L_e (u·n_out)_e (x_e − x_c), exact for a uniform
 * field on a flat polygon), projected onto the tangent plane at the centre. 3 values per cell.
 * GPU pass 1 of the step (docs/flow.md#the-step).
 */
export function reconstructCellVelocity(grid: CubeSphereGrid, edgeVelocity: Float64Array, out: Float64Array): void {
  const { center, area, cellEdge, cellEdgeSign, edgeLength, edgeMid } = grid;
  for (let c = 0; c < grid.cellCount; c++) {
    const cx = center[3 * c]!;
    const cy = center[3 * c + 1]!;
    const cz = center[3 * c + 2]!;
    let ux = 0;
    let uy = 0;
    let uz = 0;
    for (let s = 0; s < 4; s++) {
      const e = cellEdge[4 * c + s]!;
      const flux = cellEdgeSign[4 * c + s]! * edgeVelocity[e]! * edgeLength[e]!;
      ux += flux * (edgeMid[3 * e]! - cx);
      uy += flux * (edgeMid[3 * e + 1]! - cy);
      uz += flux * (edgeMid[3 * e + 2]! - cz);
    }
    const radial = ux * cx + uy * cy + uz * cz;
    const a = area[c]!;
    out[3 * c] = (ux - radial * cx) / a;
    out[3 * c + 1] = (uy - radial * cy) / a;
    out[3 * c + 2] = (uz - radial * cz) / a;
  }
}

/**
 * What the flow tests compare against, written from the model's published constants and not from
 * the code under test: the exponent of the stationary film and a weighted least-squares slope.
 */
import type { FilmSimulation } from '../../../../src/physics/filmDynamics/filmSimulation.ts';

/** a = ρ G R η0/(Γ0 R̄T), η0 = h̄/2: ρ = 997 kg/m³, G = 9.8 m/s², R̄ = 8.3144598 J/(mol K), T = 298.15 K. */
export const stationaryExponent = (radiusMm: number, thicknessNm: number, surfactantMolM2: number): number =>
  (997 * 9.8 * radiusMm * 1e-3 * thicknessNm * 0.5e-9) / (surfactantMolM2 * 8.3144598 * 298.15);

/** The slope of ln h against cos θ (the cell centre's z) over all cells, weighted by area. */
export function logThicknessSlope(sim: FilmSimulation): number {
  const { center, area } = sim.grid;
  let [sw, sx, sy, sxx, sxy] = [0, 0, 0, 0, 0];
  sim.state.eta.forEach((eta, c) => {
    const [w, x, y] = [area[c]!, center[3 * c + 2]!, Math.log(eta)];
    sw += w;
    sx += w * x;
    sy += w * y;
    sxx += w * x * x;
    sxy += w * x * y;
  });
  return (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
}

/** The largest relative difference between two fields. */
export function maxRelativeDifference(a: Float64Array, b: Float64Array): number {
  let max = 0;
  a.forEach((x, i) => (max = Math.max(max, Math.abs(x - b[i]!) / Math.max(Math.abs(x), Math.abs(b[i]!), 1e-300))));
  return max;
}

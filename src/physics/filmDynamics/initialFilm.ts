import { mulberry32 } from '../seededRandom.ts';
import type { CubeSphereGrid } from './cubeSphereGrid.ts';

/** Bumps in a seeded perturbation, their angular width (radians) and their largest log-amplitude. */
const BUMPS = 8;
const BUMP_WIDTH_RAD = 0.35;
const BUMP_LOG_AMPLITUDE = 0.15;

/**
 * The film at t = 0: η and Γ (in η0 and Γ0), Γ/η = 1 everywhere. Seed 0 is the uniform film
 * η = Γ = 1; any other seed multiplies it by exp(Σ_k a_k exp(−(1 − x·c_k)/w²)), BUMPS smooth bumps
 * at centres c_k uniform on the sphere with log-amplitudes a_k uniform in ±BUMP_LOG_AMPLITUDE
 * (mulberry32(seed), so the same seed gives the same film everywhere), then rescaled so the mean
 * over the sphere's area is exactly 1 (the mean thickness stays the parameter's).
 */
export function initialFilm(grid: CubeSphereGrid, seed: number): { eta: Float64Array; gamma: Float64Array } {
  const eta = new Float64Array(grid.cellCount).fill(1);
  if (seed !== 0) {
    const random = mulberry32(seed);
    const bumps = Array.from({ length: BUMPS }, () => {
      const z = 2 * random() - 1;
      const phi = 2 * Math.PI * random();
      const r = Math.sqrt(1 - z * z);
      return { x: r * Math.cos(phi), y: r * Math.sin(phi), z, amplitude: BUMP_LOG_AMPLITUDE * (2 * random() - 1) };
    });
    let volume = 0;
    let totalArea = 0;
    for (let c = 0; c < grid.cellCount; c++) {
      const [x, y, z] = [grid.center[3 * c]!, grid.center[3 * c + 1]!, grid.center[3 * c + 2]!];
      let exponent = 0;
      for (const b of bumps) exponent += b.amplitude * Math.exp(-(1 - (x * b.x + y * b.y + z * b.z)) / BUMP_WIDTH_RAD ** 2);
      eta[c] = Math.exp(exponent);
      volume += grid.area[c]! * eta[c]!;
      totalArea += grid.area[c]!;
    }
    for (let c = 0; c < grid.cellCount; c++) eta[c] = (eta[c]! * totalArea) / volume;
  }
  return { eta, gamma: Float64Array.from(eta) };
}

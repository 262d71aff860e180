import { describe, expect, it } from 'vitest';
import { environmentRadiance, equirectUv, reflectedRadiance } from '../../../src/bubbleTwins/environment.ts';
import type { EnvironmentPixels } from '../../../src/bubbleMaterials/environmentMaps.ts';
import { ALGEBRAIC_TOL, EQUIRECT_SEAM_TOL, ROUNDING_TOL } from '../../tolerances.ts';

/** A small synthetic map whose texel (i, j) holds (i, j, i·j). */
const W = 16,
  H = 8;
const MAP: EnvironmentPixels = {
  width: W,
  height: H,
  rgba: Float32Array.from({ length: 4 * W * H }, (_, k) => {
    const texel = k >> 2,
      i = texel % W,
      j = Math.floor(texel / W);
    return [i, j, i * j, 1][k & 3]!;
  }),
};

/** The unit direction that three's equirectangular convention maps to (u, v). */
const direction = (u: number, v: number): [number, number, number] => {
  const azimuth = (u - 0.5) * 2 * Math.PI,
    elevation = (v - 0.5) * Math.PI;
  return [Math.cos(elevation) * Math.cos(azimuth), Math.sin(elevation), Math.cos(elevation) * Math.sin(azimuth)];
};
const turn = ([x, y, z]: readonly number[], deg: number): [number, number, number] => {
  const a = (deg * Math.PI) / 180;
  // The inverse of the lookup's turn: a feature at azimuth φ moves to φ + deg.
  return [Math.cos(a) * x! + Math.sin(a) * z!, y!, -Math.sin(a) * x! + Math.cos(a) * z!];
};

describe('the equirectangular environment', () => {
  it('looks straight up at v = 1 and straight down at v = 0', () => {
    expect(Math.abs(equirectUv([0, 1, 0], 0)[1] - 1)).toBeLessThan(ROUNDING_TOL);
    expect(Math.abs(equirectUv([0, -1, 0], 0)[1])).toBeLessThan(ROUNDING_TOL);
  });

  it('turned by θ, shows at the turned direction what it showed unturned (and a full turn is none)', () => {
    for (const deg of [0, 37, 90, 180, 333]) {
      for (const d of [direction(0.1, 0.5), direction(0.7, 0.2), direction(0.45, 0.9)]) {
        const [u0, v0] = equirectUv(d, 0);
        const [u, v] = equirectUv(turn(d, deg), deg);
        // u wraps round: compare on the circle.
        expect(Math.abs(Math.sin(Math.PI * (u - u0))), `${deg}°`).toBeLessThan(ALGEBRAIC_TOL);
        expect(Math.abs(v - v0)).toBeLessThan(ROUNDING_TOL);
      }
      const d = direction(0.3, 0.6);
      const fullTurn = environmentRadiance(d, { kind: 'map', pixels: MAP, rotationDeg: 360 })[2];
      expect(Math.abs(fullTurn - environmentRadiance(d, { kind: 'map', pixels: MAP, rotationDeg: 0 })[2])).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it("returns a texel's own value at its centre, as a GPU's bilinear filter does", () => {
    for (const [i, j] of [
      [0, 0],
      [3, 5],
      [15, 7],
      [8, 2],
    ] as const) {
      const rgb = environmentRadiance(direction((i + 0.5) / W, (j + 0.5) / H), { kind: 'map', pixels: MAP, rotationDeg: 0 });
      expect(Math.abs(rgb[0] - i)).toBeLessThan(ALGEBRAIC_TOL);
      expect(Math.abs(rgb[1] - j)).toBeLessThan(ALGEBRAIC_TOL);
      expect(Math.abs(rgb[2] - i * j)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it('is continuous across the seam where u wraps from 1 to 0 (halfway between the last and first columns)', () => {
    const env = { kind: 'map', pixels: MAP, rotationDeg: 0 } as const;
    const v = 3.5 / H;
    const justBefore = environmentRadiance(direction(1 - 1e-9, v), env);
    const justAfter = environmentRadiance(direction(1e-9, v), env);
    expect(Math.abs(justBefore[0] - (W - 1) / 2)).toBeLessThan(EQUIRECT_SEAM_TOL);
    expect(Math.abs(justAfter[0] - (W - 1) / 2)).toBeLessThan(EQUIRECT_SEAM_TOL);
  });
});

describe('the uniform coloured environment', () => {
  it('sends its colour from every direction, of any length, and the walls reflect that colour (not the white that none gives them)', () => {
    const env = { kind: 'color', color: [1, 0.2, 3.5] } as const;
    for (const d of [direction(0.1, 0.5), direction(0.7, 0.02), direction(0.45, 0.99), [0, -7, 0] as [number, number, number]]) {
      expect(environmentRadiance(d, env)).toEqual([1, 0.2, 3.5]);
      expect(reflectedRadiance(d, env)).toEqual([1, 0.2, 3.5]);
    }
    expect(reflectedRadiance([0, 0, 1], { kind: 'color', color: [0, 0, 0] })).toEqual([0, 0, 0]);
  });
});

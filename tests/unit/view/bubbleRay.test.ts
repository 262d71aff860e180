/**
 * Where a point of the view meets the bubble (src/view/bubbleRay.ts), shared by a press's blow and
 * burst and by the probe's angle: checked against the geometry of a ray from a camera on +z at
 * distance D meeting the unit sphere, solved here by the quadratic and the law of sines.
 */
import { PerspectiveCamera } from 'three';
import { describe, expect, it } from 'vitest';
import { bubbleHit } from '../../../src/view/bubbleRay.ts';
import { incidenceAngleDeg } from '../../../src/view/probe.ts';

const [FOV_DEG, ASPECT, D] = [35, 2, 4];
const camera = new PerspectiveCamera(FOV_DEG, ASPECT, 0.1, 100);
camera.position.set(0, 0, D);
const HALF_FOV_TAN = Math.tan((FOV_DEG * Math.PI) / 360);

/** The near point where a ray from (0, 0, D) at angle α off the axis, towards +y, meets the unit sphere: t = D cos α − √(1 − D² sin² α). */
function nearHit(alpha: number): [number, number] {
  const t = D * Math.cos(alpha) - Math.sqrt(1 - D * D * Math.sin(alpha) ** 2);
  return [t * Math.sin(alpha), D - t * Math.cos(alpha)];
}

/** Each component of `actual` within 1e-12 of `expected`'s. */
function expectNear(actual: readonly number[], expected: readonly number[]): void {
  expect(actual).toHaveLength(expected.length);
  actual.forEach((v, i) => expect(v).toBeCloseTo(expected[i]!, 12));
}

describe('bubbleHit', () => {
  it("meets the bubble's front at the view's centre, looking straight at it", () => {
    const hit = bubbleHit(camera, [0.5, 0.5])!;
    expectNear(hit.point.toArray(), [0, 0, 1]);
    expectNear(hit.ray.direction.toArray(), [0, 0, -1]);
  });

  it('meets the near wall where the quadratic puts it, up the view and across it (the aspect widens x)', () => {
    const up = Math.atan(0.2 * HALF_FOV_TAN); // fy = 0.4: a fifth of the half view above the centre
    const [y, z] = nearHit(up);
    expectNear(bubbleHit(camera, [0.5, 0.4])!.point.toArray(), [0, y, z]);
    const right = Math.atan(0.2 * HALF_FOV_TAN * ASPECT); // fx = 0.6
    const [x, zx] = nearHit(right);
    expectNear(bubbleHit(camera, [0.6, 0.5])!.point.toArray(), [x, 0, zx]);
  });

  it("misses beyond the bubble's rim (its angular radius from the camera is asin(1/D) = 14.5°, the view's half height 17.5°)", () => {
    expect(bubbleHit(camera, [0.5, 0])).toBeNull();
    expect(bubbleHit(camera, [0, 0.5])).toBeNull();
  });

  it("gives the probe's angle of incidence, asin(D sin α) by the law of sines", () => {
    const up = Math.atan(0.5 * HALF_FOV_TAN); // fy = 0.25
    const expected = (Math.asin(D * Math.sin(up)) * 180) / Math.PI;
    expect(incidenceAngleDeg(camera, 0.5, 0.25)).toBeCloseTo(expected, 9);
    expect(incidenceAngleDeg(camera, 0.5, 0.5)).toBeCloseTo(0, 9);
  });
});

import { type PerspectiveCamera, type Ray, Raycaster, Sphere, Vector2, Vector3 } from 'three';

const UNIT_SPHERE = new Sphere(new Vector3(), 1);

/** A view ray and the point where it first meets the unit bubble (its near wall). */
export interface BubbleHit {
  readonly ray: Ray;
  readonly point: Vector3;
}

/**
 * The camera's ray through a point of the view (fractions from the top left: x to the right, y
 * down) and where it first meets the unit bubble centred at the origin, or null where it misses:
 * where a press, a blow or the probe lands on the bubble.
 */
export function bubbleHit(camera: PerspectiveCamera, [fx, fy]: readonly [number, number]): BubbleHit | null {
  camera.updateMatrixWorld();
  const raycaster = new Raycaster();
  raycaster.setFromCamera(new Vector2(2 * fx - 1, 1 - 2 * fy), camera);
  const point = raycaster.ray.intersectSphere(UNIT_SPHERE, new Vector3());
  return point && { ray: raycaster.ray, point };
}

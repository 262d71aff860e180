import type { PerspectiveCamera } from 'three';
import type { Vec3 } from '../fields/thicknessField.ts';
import { FLOW_PARAMETERS } from '../physics/filmDynamics/flowParameters.ts';
import { bubbleHit } from './bubbleRay.ts';

/** The fastest blow: the wind's upper end. */
const BLOW_MAX_MPS = FLOW_PARAMETERS.find((r) => r.key === 'windMps')!.domain.max;

/**
 * Where air blown at a point of the view (fractions from the top left) lands on the unit bubble,
 * and its velocity in m/s: the screen velocity (CSS pixels per second, right and down) as fast
 * as that moves over the bubble's surface of radius `radiusMm` at the point's distance, at most
 * BLOW_MAX_MPS. Null off the bubble.
 */
export function blowOnBubble(
  camera: PerspectiveCamera,
  viewHeightPx: number,
  radiusMm: number,
  at: readonly [number, number],
  [vxPx, vyPx]: readonly [number, number],
): { readonly point: Vec3; readonly velocityMps: Vec3 } | null {
  const hit = bubbleHit(camera, at)?.point;
  if (!hit) return null;
  // Metres per CSS pixel at the point's distance (the camera looks along −z: x right, y up).
  const viewHeight = 2 * hit.distanceTo(camera.position) * Math.tan((camera.fov * Math.PI) / 360);
  const metresPerPixel = (viewHeight / viewHeightPx) * radiusMm * 1e-3;
  const speed = Math.hypot(vxPx, vyPx) * metresPerPixel;
  const scale = (speed > BLOW_MAX_MPS ? BLOW_MAX_MPS / speed : 1) * metresPerPixel;
  return { point: [hit.x, hit.y, hit.z], velocityMps: [vxPx * scale, -vyPx * scale, 0] };
}

/** Rays per hole: the rim is a polygon in polar coordinates about the hole's centre. */
export const HOLE_RAYS = 64;
/** At most this many holes are tracked; a cell rupturing beyond them just opens (the others' rims sweep on). */
export const MAX_HOLES = 16;

/**
 * A hole in the film: a centre, a tangent frame (e1, e2) there and the rim's angular radius along
 * HOLE_RAYS directions ψ_k = 2πk/HOLE_RAYS. Each ray advances at the Taylor–Culick speed of the
 * film just ahead of it (docs/flow.md#rupture-and-bursting).
 */
export interface FilmHole {
  readonly center: readonly [number, number, number];
  readonly e1: readonly [number, number, number];
  readonly e2: readonly [number, number, number];
  readonly radius: Float64Array;
}

export function newHole(x: number, y: number, z: number): FilmHole {
  const r = Math.hypot(x, y, z);
  const c: [number, number, number] = [x / r, y / r, z / r];
  // e1: the axis least aligned with c, made orthogonal to it; e2 = c × e1.
  const axis = Math.abs(c[0]) < 0.6 ? [1, 0, 0] : Math.abs(c[1]) < 0.6 ? [0, 1, 0] : [0, 0, 1];
  const d = axis[0]! * c[0] + axis[1]! * c[1] + axis[2]! * c[2];
  const t = [axis[0]! - d * c[0], axis[1]! - d * c[1], axis[2]! - d * c[2]];
  const tr = Math.hypot(t[0]!, t[1]!, t[2]!);
  const e1: [number, number, number] = [t[0]! / tr, t[1]! / tr, t[2]! / tr];
  const e2: [number, number, number] = [c[1] * e1[2] - c[2] * e1[1], c[2] * e1[0] - c[0] * e1[2], c[0] * e1[1] - c[1] * e1[0]];
  return { center: c, e1, e2, radius: new Float64Array(HOLE_RAYS) };
}

/** The point at angular distance `distance` from the hole's centre along ray direction ψ. */
export function pointOnRay(hole: FilmHole, psi: number, distance: number, out: Float64Array): void {
  const cs = Math.cos(distance);
  const sn = Math.sin(distance);
  const [cp, sp] = [Math.cos(psi), Math.sin(psi)];
  for (let k = 0; k < 3; k++) out[k] = cs * hole.center[k]! + sn * (cp * hole.e1[k]! + sp * hole.e2[k]!);
}

/** Whether direction (x, y, z) (unit) lies inside the hole: its angular distance below the rim's, interpolated between rays. */
export function insideHole(hole: FilmHole, x: number, y: number, z: number): boolean {
  const [c, e1, e2] = [hole.center, hole.e1, hole.e2];
  const along = x * c[0] + y * c[1] + z * c[2];
  const u = x * e1[0] + y * e1[1] + z * e1[2];
  const v = x * e2[0] + y * e2[1] + z * e2[2];
  const distance = Math.atan2(Math.hypot(u, v), along);
  const position = ((Math.atan2(v, u) / (2 * Math.PI) + 1) % 1) * HOLE_RAYS;
  const k = Math.floor(position) % HOLE_RAYS;
  const w = position - Math.floor(position);
  const rim = (1 - w) * hole.radius[k]! + w * hole.radius[(k + 1) % HOLE_RAYS]!;
  return distance < rim;
}

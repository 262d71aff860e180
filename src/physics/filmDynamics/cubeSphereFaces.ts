/**
 * The six faces of the equiangular gnomonic cube-sphere. A face is a normal n and two axes u, v
 * with u × v = n; the point at angles (α, β) ∈ [−π/4, π/4]² is the unit vector along
 * n + tan α u + tan β v. The bubble's top (θ = 0) is +z, the centre of face 4.
 * docs/flow.md#the-grid.
 */
export interface CubeFace {
  readonly n: readonly [number, number, number];
  readonly u: readonly [number, number, number];
  readonly v: readonly [number, number, number];
}

export const CUBE_FACES: readonly CubeFace[] = [
  { n: [1, 0, 0], u: [0, 1, 0], v: [0, 0, 1] },
  { n: [-1, 0, 0], u: [0, -1, 0], v: [0, 0, 1] },
  { n: [0, 1, 0], u: [0, 0, 1], v: [1, 0, 0] },
  { n: [0, -1, 0], u: [0, 0, -1], v: [1, 0, 0] },
  { n: [0, 0, 1], u: [1, 0, 0], v: [0, 1, 0] },
  { n: [0, 0, -1], u: [-1, 0, 0], v: [0, 1, 0] },
];

/** The face a direction (not necessarily unit) falls on and its gnomonic coordinates tan α, tan β. */
export interface FacePoint {
  face: number;
  tanA: number;
  tanB: number;
}

/** Which face (the largest component; ties go to x, then y) and where on it, written into `out`. */
export function facePoint(x: number, y: number, z: number, out: FacePoint): FacePoint {
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  const az = Math.abs(z);
  const face = ax >= ay && ax >= az ? (x >= 0 ? 0 : 1) : ay >= az ? (y >= 0 ? 2 : 3) : z >= 0 ? 4 : 5;
  const f = CUBE_FACES[face]!;
  const dn = x * f.n[0] + y * f.n[1] + z * f.n[2];
  out.face = face;
  out.tanA = (x * f.u[0] + y * f.u[1] + z * f.u[2]) / dn;
  out.tanB = (x * f.v[0] + y * f.v[1] + z * f.v[2]) / dn;
  return out;
}

/** The unit vector at gnomonic coordinates (tan α, tan β) of `face`, written into out[offset..offset+2]. */
export function faceDirection(face: number, tanA: number, tanB: number, out: Float64Array, offset: number): void {
  const f = CUBE_FACES[face]!;
  const x = f.n[0] + tanA * f.u[0] + tanB * f.v[0];
  const y = f.n[1] + tanA * f.u[1] + tanB * f.v[1];
  const z = f.n[2] + tanA * f.u[2] + tanB * f.v[2];
  const r = Math.hypot(x, y, z);
  out[offset] = x / r;
  out[offset + 1] = y / r;
  out[offset + 2] = z / r;
}

/**
 * The solid angle of the gnomonic rectangle [0, x] × [0, y] on a face (x = tan α, y = tan β):
 * atan(xy/√(1 + x² + y²)). Differences of it give each cell's exact area.
 */
export const gnomonicSolidAngle = (x: number, y: number): number => Math.atan((x * y) / Math.sqrt(1 + x * x + y * y));

/** Each face's n, u, v as the columns of a 3 × 3 matrix, face after face (a shader's `mat3 uCubeFaces[6]`). */
export const cubeFaceColumns = (): number[] => CUBE_FACES.flatMap((f) => [...f.n, ...f.u, ...f.v]);

// The six faces of the equiangular gnomonic cube-sphere (mirrors src/physics/filmDynamics/cubeSphereFaces.ts):
// uCubeFaces[f] holds the face's normal n and axes u, v as its columns (CUBE_FACES, set from TypeScript).
#ifndef THIN_FILM_CUBE_SPHERE_FACES
#define THIN_FILM_CUBE_SPHERE_FACES
uniform mat3 uCubeFaces[6];

/** The face a direction falls on (the largest component; ties go to x, then y) and its gnomonic (tan α, tan β). */
vec2 tfcFacePoint(vec3 p, out int face) {
  vec3 a = abs(p);
  face = a.x >= a.y && a.x >= a.z ? (p.x >= 0.0 ? 0 : 1) : a.y >= a.z ? (p.y >= 0.0 ? 2 : 3) : p.z >= 0.0 ? 4 : 5;
  mat3 f = uCubeFaces[face];
  return vec2(dot(p, f[1]), dot(p, f[2])) / dot(p, f[0]);
}
#endif

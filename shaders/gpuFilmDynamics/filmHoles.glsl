// The tracked holes of the film (mirrors src/physics/filmDynamics/filmHoles.ts) as one texture, the hole
// table (its layout from src/gpuFilmDynamics/flowLayouts.ts, its texels records of src/gpuFilmDynamics/flowTexels.ts):
// hole s is row s, its rim's angular radius along ray k in texel (k, s), a HOLE_RAY, for the
// TFC_HOLE_RAYS rays, then its frame in the texels named TFC_HOLE_CENTER_TEXEL (a HOLE_ORIGIN: the
// centre, and whether the slot holds a hole), TFC_HOLE_E1_TEXEL and TFC_HOLE_E2_TEXEL (a HOLE_AXIS
// each); TFC_MAX_HOLES rows.
#ifndef THIN_FILM_FILM_HOLES
#define THIN_FILM_FILM_HOLES
#include "texelRecord.glsl"
const float TFC_HOLE_PI = 3.14159265358979;

struct TfcHole {
  vec3 center;
  vec3 e1;
  vec3 e2;
  bool open;
};

/** The rim's angular radius along ray k of hole s. */
float tfcRayRadius(sampler2D holes, int k, int s) {
  vec4 ray = texelFetch(holes, ivec2(k, s), 0);
  return TFC_TEXEL_FLOAT(ray, TFC_HOLE_RAY_RADIUS);
}

/** A ray's texel at radius r. */
vec4 tfcRayTexel(float r) {
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_HOLE_RAY_RADIUS, r);
  return texel;
}

vec3 tfcHoleAxis(sampler2D holes, int k, int s) {
  vec4 axis = texelFetch(holes, ivec2(k, s), 0);
  return TFC_TEXEL_VEC3(axis, TFC_HOLE_AXIS_AXIS);
}

TfcHole tfcReadHole(sampler2D holes, int s) {
  vec4 origin = texelFetch(holes, ivec2(TFC_HOLE_CENTER_TEXEL, s), 0);
  return TfcHole(
    TFC_TEXEL_VEC3(origin, TFC_HOLE_ORIGIN_CENTER),
    tfcHoleAxis(holes, TFC_HOLE_E1_TEXEL, s),
    tfcHoleAxis(holes, TFC_HOLE_E2_TEXEL, s),
    TFC_TEXEL_FLOAT(origin, TFC_HOLE_ORIGIN_OPEN) != 0.0
  );
}

/** newHole: the centre p normalised, e1 the axis least aligned with it made orthogonal to it, e2 = c × e1. */
TfcHole tfcNewHole(vec3 p) {
  vec3 c = normalize(p);
  vec3 axis = abs(c.x) < 0.6 ? vec3(1.0, 0.0, 0.0) : abs(c.y) < 0.6 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
  vec3 e1 = normalize(axis - dot(axis, c) * c);
  return TfcHole(c, e1, cross(c, e1), true);
}

/** The texel (k, s) of a hole's row: its frame's texels, and ray k's radius for k < TFC_HOLE_RAYS (a new hole's are 0). */
vec4 tfcHoleTexel(TfcHole h, int k) {
  vec4 texel = vec4(0.0);
  if (k == TFC_HOLE_CENTER_TEXEL) {
    TFC_SET_TEXEL_VEC3(texel, TFC_HOLE_ORIGIN_CENTER, h.center);
    TFC_SET_TEXEL_FLOAT(texel, TFC_HOLE_ORIGIN_OPEN, h.open ? 1.0 : 0.0);
  } else if (k == TFC_HOLE_E1_TEXEL) {
    TFC_SET_TEXEL_VEC3(texel, TFC_HOLE_AXIS_AXIS, h.e1);
  } else if (k == TFC_HOLE_E2_TEXEL) {
    TFC_SET_TEXEL_VEC3(texel, TFC_HOLE_AXIS_AXIS, h.e2);
  } else {
    texel = tfcRayTexel(0.0);
  }
  return texel;
}

/** pointOnRay: the point at angular distance `distance` from the hole's centre along ray direction ψ. */
vec3 tfcPointOnRay(TfcHole h, float psi, float distance) {
  return cos(distance) * h.center + sin(distance) * (cos(psi) * h.e1 + sin(psi) * h.e2);
}

/** insideHole: whether direction p (unit) lies inside hole s, its rim interpolated between rays. */
bool tfcInsideHole(sampler2D holes, int s, TfcHole h, vec3 p) {
  float u = dot(p, h.e1);
  float v = dot(p, h.e2);
  float distance = atan(length(vec2(u, v)), dot(p, h.center));
  // atan(0, 0) is undefined in GLSL (0 in JavaScript): at the centre any ray will do.
  float psi = u == 0.0 && v == 0.0 ? 0.0 : atan(v, u);
  float position = fract(psi / (2.0 * TFC_HOLE_PI) + 1.0) * float(TFC_HOLE_RAYS);
  int k = int(floor(position)) % TFC_HOLE_RAYS;
  float w = position - floor(position);
  return distance < mix(tfcRayRadius(holes, k, s), tfcRayRadius(holes, (k + 1) % TFC_HOLE_RAYS, s), w);
}

/** Whether direction p (unit) lies inside any open hole. */
bool tfcInsideAnyHole(sampler2D holes, vec3 p) {
  for (int s = 0; s < TFC_MAX_HOLES; s++) {
    TfcHole h = tfcReadHole(holes, s);
    if (h.open && tfcInsideHole(holes, s, h, p)) return true;
  }
  return false;
}
#endif

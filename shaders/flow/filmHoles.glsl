// The tracked holes of the film (mirrors src/physics/flow/filmHoles.ts) as one texture, the hole
// table (its layout from src/flow/flowLayouts.ts): hole s is row s, its rim's angular radius along
// ray k in texel (k, s).r for the TFC_HOLE_RAYS rays, then its frame in the texels named
// TFC_HOLE_CENTER_TEXEL (xyz, and w = 1 while the slot holds a hole), TFC_HOLE_E1_TEXEL and
// TFC_HOLE_E2_TEXEL; TFC_MAX_HOLES rows.
#ifndef THIN_FILM_FILM_HOLES
#define THIN_FILM_FILM_HOLES
const float TFC_HOLE_PI = 3.14159265358979;

struct TfcHole {
  vec3 center;
  vec3 e1;
  vec3 e2;
  bool open;
};

TfcHole tfcReadHole(sampler2D holes, int s) {
  vec4 c = texelFetch(holes, ivec2(TFC_HOLE_CENTER_TEXEL, s), 0);
  vec3 e1 = texelFetch(holes, ivec2(TFC_HOLE_E1_TEXEL, s), 0).xyz;
  vec3 e2 = texelFetch(holes, ivec2(TFC_HOLE_E2_TEXEL, s), 0).xyz;
  return TfcHole(c.xyz, e1, e2, c.w != 0.0);
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
  if (k == TFC_HOLE_CENTER_TEXEL) return vec4(h.center, 1.0);
  if (k == TFC_HOLE_E1_TEXEL) return vec4(h.e1, 0.0);
  if (k == TFC_HOLE_E2_TEXEL) return vec4(h.e2, 0.0);
  return vec4(0.0);
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
  float a = texelFetch(holes, ivec2(k, s), 0).r;
  float b = texelFetch(holes, ivec2((k + 1) % TFC_HOLE_RAYS, s), 0).r;
  return distance < mix(a, b, w);
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

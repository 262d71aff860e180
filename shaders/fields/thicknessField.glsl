// Film thickness over the bubble, deterministic in uTimeSeconds. p: a point on the unit sphere,
// y up. TFC_THICKNESS_FIELD _UNIFORM | _DRAINAGE | _SWIRL. Mirrors src/fields/thicknessField.ts.
#ifndef THIN_FILM_THICKNESS_FIELD
#define THIN_FILM_THICKNESS_FIELD

uniform float uThicknessNm;
uniform float uThicknessRangeNm;
uniform float uSwirlSpeed;
uniform float uTimeSeconds;

float tfcThicknessAt(vec3 p) {
#if TFC_THICKNESS_FIELD == TFC_THICKNESS_FIELD_UNIFORM
  return uThicknessNm;
#else
  float h = p.y;
#if TFC_THICKNESS_FIELD == TFC_THICKNESS_FIELD_SWIRL
  // Swirling bands: the height is advected around the vertical axis by a slow, smooth flow.
  float t = uTimeSeconds * uSwirlSpeed;
  float azimuth = atan(p.z, p.x);
  h += 0.12 * sin(3.0 * azimuth + 2.0 * h + t) + 0.07 * sin(5.0 * azimuth - 3.0 * h - 1.7 * t) + 0.05 * sin(9.0 * h + 0.6 * t);
#endif
  // Gravity drains the film: thin at the top, thick at the bottom ...
  float d = uThicknessNm - 0.5 * uThicknessRangeNm * clamp(h, -1.0, 1.0);
  // ... down to a black film of ~10 nm in a cap at the top.
  d = mix(max(d, 10.0), 10.0, smoothstep(0.82, 0.95, p.y));
  return clamp(d, 0.0, 20000.0);
#endif
}

#endif

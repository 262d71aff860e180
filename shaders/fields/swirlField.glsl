// The drained film stirred around the vertical axis, deterministic in uTimeSeconds: the height is
// displaced by three travelling waves. Mirrors src/fields/swirlField.ts.
#include "drainedFilm.glsl"
uniform float uSwirlSpeed;
uniform float uTimeSeconds;

float tfcThicknessAt(vec3 p) {
  float t = uTimeSeconds * uSwirlSpeed;
  float azimuth = atan(p.z, p.x);
  float h = p.y + 0.12 * sin(3.0 * azimuth + 2.0 * p.y + t) + 0.07 * sin(5.0 * azimuth - 3.0 * p.y - 1.7 * t) + 0.05 * sin(9.0 * p.y + 0.6 * t);
  return tfcDrainedThicknessNm(h, p.y);
}

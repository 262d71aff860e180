// The bubble (twin of bubbleRadiance in src/bubbleTwins/cpuBubbleImage.ts): the near wall reflects the environment in its mirror direction (the illuminant's
// white with TFC_ENVIRONMENT 0) weighted by the film's reflectance; through it (T = 1 - R: tfcWallRadiance)
// the far wall, seen from inside at the same θ_i, reflecting the environment in its own mirror
// direction, and through both walls the environment behind. Left out: the third wall the far
// wall's reflection crosses on its way in, and every reflection of higher order (each ≤ R² ≈ 2e-3
// of the light for soap). uExposure scales all of it, as it scales the background; three.js's tone
// mapping (renderer.toneMapping) then maps it to the display. An opaque inside (TFC_OPAQUE_INSIDE, a
// metal: filmMedia.glsl) transmits nothing: a coated solid sphere, no far wall and nothing behind.
// Defines: TFC_FILM_MODE, TFC_THICKNESS_FIELD, TFC_SIDES (_FRONT | _BOTH), TFC_ENVIRONMENT, TFC_HATCH_OUT_OF_GAMUT;
// TFC_PROBE (src/view/probe.ts) outputs the near wall's film XYZ and thickness instead of a colour.
// tfcThicknessAt(p): the field's GLSL, placed before this file (src/bubbleMaterials/thicknessFieldSource.ts).
#include "filmColor.glsl"
#include "colorConversions.glsl"
#include "environment.glsl"

uniform mat3 uXyzToLinearDisplay;   // XYZ -> the display's linear space, for the gamut test

#ifdef TFC_ENVIRONMENT_MATRIX
// The light's tint t: of each colour c the walls reflect they reflect t c, through M (the film's
// matrix under the untinted light), so a change of tint is a change of this uniform alone.
#include "filmLightTint.glsl"

// The film's XYZ under the light, its tint included (what the probe reads and the gamut test tests).
vec3 tfcFilmLightXyz(mat3 m) { return m * uLightTint; }
#else
vec3 tfcFilmLightXyz(vec3 xyz) { return xyz; }
#endif

// A wall's light: its film's reflection of `reflected` (the light from its mirror direction) and its
// transmission of `transmitted`, in the working space. Where the walls reflect the untinted light's
// white (TFC_ENVIRONMENT_NONE), the film's XYZ gives R per channel and T = 1 - R; in a coloured
// environment or a tinted light its environment matrix (TFC_ENVIRONMENT_MATRIX) gives each colour c
// as M t c, an integral of two spectra, and c - M c through the wall, the light the film does not reflect.
vec3 tfcWallRadiance(TFC_FILM_COLOR film, vec3 reflected, vec3 transmitted) {
#ifdef TFC_ENVIRONMENT_MATRIX
  mat3 m = uXyzToLinearWorking * film;
  return m * (uLightTint * reflected) + transmitted - m * transmitted;
#else
  vec3 r = tfcApplyMatrix3(uXyzToLinearWorking, film);
  return r * reflected + clamp(1.0 - r, 0.0, 1.0) * transmitted;
#endif
}

varying vec3 vWorldPosition;
varying vec3 vWorldNormal;
varying vec3 vSpherePoint;

void main() {
  vec3 toEye = normalize(cameraPosition - vWorldPosition);
  vec3 normal = normalize(vWorldNormal);
  float cosIncidence = clamp(abs(dot(normal, toEye)), 0.0, 1.0);
  float nearThicknessNm = tfcThicknessAt(vSpherePoint);
  TFC_FILM_COLOR nearFilm = tfcFilmXyz(nearThicknessNm, cosIncidence, false);
  vec3 nearXyz = tfcFilmLightXyz(nearFilm);
#ifdef TFC_PROBE
  gl_FragColor = vec4(nearXyz, nearThicknessNm);
  return;
#endif
  vec3 nearLight = tfcReflectedRadiance(reflect(-toEye, normal));
#ifdef TFC_OPAQUE_INSIDE
  vec3 behind = vec3(0.0);
#else
  vec3 behind = tfcEnvironmentRadiance(-toEye);
#endif
#if TFC_SIDES == TFC_SIDES_BOTH && !defined(TFC_OPAQUE_INSIDE)
  // The chord through a unit sphere at incidence θ has length 2 cos θ; the exit point's film is
  // met at the same θ from inside. (Object space = world space up to the sphere's scale.)
  vec3 farPoint = normalize(vSpherePoint - 2.0 * cosIncidence * toEye);
  TFC_FILM_COLOR farFilm = tfcFilmXyz(tfcThicknessAt(farPoint), cosIncidence, true);
  // Seen from inside, the far wall's normal points inward (-farPoint); reflect() is sign-blind.
  behind = tfcWallRadiance(farFilm, tfcReflectedRadiance(reflect(-toEye, farPoint)), behind);
#endif
  vec3 color = uExposure * tfcWallRadiance(nearFilm, nearLight, behind);
#if TFC_HATCH_OUT_OF_GAMUT
  vec3 display = tfcApplyMatrix3(uXyzToLinearDisplay, uExposure * nearXyz);
  if (tfcOutsideGamut(display) && mod(gl_FragCoord.x + gl_FragCoord.y, 8.0) < 2.0) color = vec3(1.0, 0.0, 1.0);
#endif
  gl_FragColor = vec4(color, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}

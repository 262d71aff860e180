// What the walls reflect and the background shows (twin of src/bubbleTwins/environment.ts), in linear
// sRGB: TFC_ENVIRONMENT _NONE (black) | _SKY a procedural sky (blue zenith, pale horizon, dark green
// ground) | _MAP an equirectangular HDR map (uEnvironmentMap: u wraps round the horizon, v = 1 straight
// up) turned about +y by the angle whose (cos, sin) is uEnvironmentTurn | _COLOR one colour from every
// direction, uEnvironmentColor (relative to the light's white; a new colour is a new uniform value,
// not a new program). uExposure scales all light
// (the environment's and the film's), as environmentUniforms (src/bubbleMaterials/environmentMaterial.ts) sets it.
#ifndef THIN_FILM_ENVIRONMENT
#define THIN_FILM_ENVIRONMENT

uniform float uExposure;

#if TFC_ENVIRONMENT == TFC_ENVIRONMENT_COLOR
uniform vec3 uEnvironmentColor;
#endif

#if TFC_ENVIRONMENT == TFC_ENVIRONMENT_MAP
uniform sampler2D uEnvironmentMap;
uniform vec2 uEnvironmentTurn;

// three.js's equirectUv of the direction turned back by the map's rotation.
vec2 tfcEquirectUv(vec3 d) {
  float c = uEnvironmentTurn.x, s = uEnvironmentTurn.y;
  vec3 turned = vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
  return vec2(atan(turned.z, turned.x) * 0.15915494309189535 + 0.5, asin(clamp(turned.y, -1.0, 1.0)) * 0.3183098861837907 + 0.5);
}
#endif

vec3 tfcEnvironmentRadiance(vec3 direction) {
#if TFC_ENVIRONMENT == TFC_ENVIRONMENT_NONE
  return vec3(0.0);
#elif TFC_ENVIRONMENT == TFC_ENVIRONMENT_SKY
  float y = normalize(direction).y;
  vec3 sky = mix(vec3(0.60, 0.70, 0.80), vec3(0.10, 0.25, 0.60), smoothstep(0.0, 0.8, y));
  vec3 ground = mix(vec3(0.20, 0.22, 0.16), vec3(0.05, 0.08, 0.04), smoothstep(0.0, -0.6, y));
  return y >= 0.0 ? sky : ground;
#elif TFC_ENVIRONMENT == TFC_ENVIRONMENT_COLOR
  return uEnvironmentColor;
#else
  // No mipmaps: the lookup's derivative jump at the u seam picks no coarse level.
  return texture2D(uEnvironmentMap, tfcEquirectUv(normalize(direction))).rgb;
#endif
}

// The light a wall reflects from the mirror direction: with TFC_ENVIRONMENT_NONE the illuminant's white
// (luminance 1 from every direction: the reference views' film colour, unchanged); otherwise
// the environment itself.
vec3 tfcReflectedRadiance(vec3 direction) {
#if TFC_ENVIRONMENT == TFC_ENVIRONMENT_NONE
  return vec3(1.0);
#else
  return tfcEnvironmentRadiance(direction);
#endif
}

#endif

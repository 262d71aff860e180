// The environment seen through the bubble: TFC_ENVIRONMENT 0 none (black) | 1 a procedural sky
// (blue zenith, pale horizon, dark green ground), in linear sRGB.
#ifndef THIN_FILM_ENVIRONMENT
#define THIN_FILM_ENVIRONMENT

vec3 environmentRadiance(vec3 direction) {
#if TFC_ENVIRONMENT == 0
  return vec3(0.0);
#else
  float y = normalize(direction).y;
  vec3 sky = mix(vec3(0.60, 0.70, 0.80), vec3(0.10, 0.25, 0.60), smoothstep(0.0, 0.8, y));
  vec3 ground = mix(vec3(0.20, 0.22, 0.16), vec3(0.05, 0.08, 0.04), smoothstep(0.0, -0.6, y));
  return y >= 0.0 ? sky : ground;
#endif
}

// The light a wall reflects from the mirror direction: with TFC_ENVIRONMENT 0 the illuminant's white
// (luminance 1 from every direction: the reference views' film colour, unchanged); otherwise
// the environment itself.
vec3 reflectedRadiance(vec3 direction) {
#if TFC_ENVIRONMENT == 0
  return vec3(1.0);
#else
  return environmentRadiance(direction);
#endif
}

#endif

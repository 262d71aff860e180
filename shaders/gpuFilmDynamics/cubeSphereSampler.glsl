// Bilinear sampling of a cell field at any direction, seamless across faces (mirrors
// src/physics/filmDynamics/cubeSphereSampler.ts): the halo pass fills a padded atlas whose ghosts are
// weighted sums of cells (uHaloTaps: TFC_HALO_TAP_TEXELS texels per padded texel, each a HALO_TAPS
// record of two (cell, weight) taps; a corner ghost is g₁ + g₂ − c, nine taps), and a sample is 4
// taps of it. Both weigh whole texels: they read no field of a record.
#ifndef THIN_FILM_CUBE_SPHERE_SAMPLER
#define THIN_FILM_CUBE_SPHERE_SAMPLER
#include "flowAtlas.glsl"
#include "cubeSphereFaces.glsl"

const float TFC_QUARTER_PI = 0.78539816339744831;

/** The continuous cell coordinates (cell centres at integers) of gnomonic coordinates (tan α, tan β) on a face of uFlowGridN cells. */
vec2 tfcCellCoordinate(vec2 tans) { return (atan(tans) + TFC_QUARTER_PI) * float(uFlowGridN) / (2.0 * TFC_QUARTER_PI) - 0.5; }

/** The padded field's bilinear value at direction p (any non-zero vector). */
vec4 tfcSamplePadded(sampler2D padded, vec3 p) {
  int face;
  vec2 uv = tfcCellCoordinate(tfcFacePoint(p, face)) + 1.0;
  // Padded coordinates lie in [0.5, n + 0.5], so the four taps are inside the padded face.
  ivec2 ij = min(ivec2(uFlowGridN), ivec2(floor(uv)));
  vec2 w = uv - vec2(ij);
  int m = uFlowGridN + 2;
  vec4 a = texelFetch(padded, tfcFaceTexel(m, face, ij), 0);
  vec4 b = texelFetch(padded, tfcFaceTexel(m, face, ij + ivec2(1, 0)), 0);
  vec4 c = texelFetch(padded, tfcFaceTexel(m, face, ij + ivec2(0, 1)), 0);
  vec4 d = texelFetch(padded, tfcFaceTexel(m, face, ij + ivec2(1, 1)), 0);
  return (1.0 - w.y) * ((1.0 - w.x) * a + w.x * b) + w.y * ((1.0 - w.x) * c + w.x * d);
}

#ifdef TFC_HALO_TAP_TEXELS
#include "texelRecord.glsl"
/** A tap's weight × the texel of its cell in `field`. */
vec4 tfcTap(sampler2D field, float cell, float weight) { return weight * texelFetch(field, tfcCellTexel(tfcIndex(cell)), 0); }

/** The halo pass (padField): the padded texel's value, a cell's own or a ghost's weighted cells of `field`. */
vec4 tfcPadField(sampler2D haloTaps, sampler2D field) {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < TFC_HALO_TAP_TEXELS; k++) {
    vec4 taps = texelFetch(haloTaps, ivec2(TFC_HALO_TAP_TEXELS * texel.x + k, texel.y), 0);
    sum += tfcTap(field, TFC_TEXEL_FLOAT(taps, TFC_HALO_TAPS_CELL_0), TFC_TEXEL_FLOAT(taps, TFC_HALO_TAPS_WEIGHT_0)) +
      tfcTap(field, TFC_TEXEL_FLOAT(taps, TFC_HALO_TAPS_CELL_1), TFC_TEXEL_FLOAT(taps, TFC_HALO_TAPS_WEIGHT_1));
  }
  return sum;
}
#endif
#endif

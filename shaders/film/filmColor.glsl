// The film's XYZ at a thickness and cos θ_i, by the method TFC_FILM_MODE selects (src/film/filmColor.ts):
//   exact: the binned spectral integral per fragment;  table: one filtered lookup;
//   fourier: the Airy series per fragment (airySeries.glsl; by bins where it has no real path or
//     needs more than TFC_AIRY_SERIES_MAX_ORDERS terms);
//   three-iridescence: three.js's iridescence (Belcour–Barla, `evalIridescence`), the benchmark's peer.
// TFC_DISPERSIVE: the film's or the inside's index depends on λ (medium.glsl); exact and fourier then
// take the dispersive bins, the table is filled from them, and uNFilm is ñ_b at the sodium D line (the peer's).
// fromInside swaps the outer and inner media (the far wall seen through the bubble); an opaque
// inside (TFC_OPAQUE_INSIDE) sends no light that way, so the film's XYZ from inside is 0.
#ifndef THIN_FILM_COLOR
#define THIN_FILM_COLOR

#include "filmMedia.glsl"

#if TFC_FILM_MODE == TFC_FILM_MODE_EXACT
#include "binnedIntegration.glsl"

vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
#ifdef TFC_DISPERSIVE
  return tfcDispersiveBinnedXyz(fromInside, thicknessNm, cosIncidence, 0);
#else
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  return tfcBinnedXyz(tfcFilmOptics(na, uNFilm, nc, thicknessNm, cosIncidence), 0.0);
#endif
}
#elif TFC_FILM_MODE == TFC_FILM_MODE_TABLE
#include "filmTableLayout.glsl"
uniform sampler2D uFilmTable;
uniform float uTableMaxThicknessNm;

vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
  // Texel centres sit at the ends of the ranges (docs/gpu.md#texel-centres: otherwise visibly off).
  vec2 uv = tfcFilmTableUv(thicknessNm, cosIncidence, uTableMaxThicknessNm);
  // The grid may fill only the texture's lower left corner (a coarse table, FilmTable).
  vec2 size = vec2(textureSize(uFilmTable, 0));
  float rowOffset = fromInside ? uFilmTableRows : 0.0;
  vec2 texel = vec2(uv.x * (uFilmTableWidth - 1.0), rowOffset + uv.y * (uFilmTableRows - 1.0)) + 0.5;
  return texture(uFilmTable, texel / size).xyz;
}
#elif TFC_FILM_MODE == TFC_FILM_MODE_FOURIER
#include "airySeries.glsl"
#include "binnedIntegration.glsl"

vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
#ifdef TFC_DISPERSIVE
  // A dispersive film or inside has no series in x alone (docs/physics.md#a-dispersive-film): the bins take it.
  return tfcDispersiveBinnedXyz(fromInside, thicknessNm, cosIncidence, 0);
#else
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  FilmOptics o = tfcFilmOptics(na, uNFilm, nc, thicknessNm, cosIncidence);
  AirySeriesTerms t[TFC_FILM_CHANNELS];
  tfcAirySeriesTermsOf(o, t);
  float x = o.opticalPathNm.x;
  return o.opticalPathNm.y == 0.0 && (TFC_AIRY_SERIES_TRUNCATED == 1 || tfcAirySeriesConvergesAt(t, x)) ? tfcAirySeriesSum(t, x) : tfcBinnedXyz(o, 0.0);
#endif
}
#elif TFC_FILM_MODE == TFC_FILM_MODE_THREE_IRIDESCENCE
#define USE_IRIDESCENCE
#include <common>
#include <iridescence_fragment>

// Its Rec.709 reflectance back to XYZ with the chunk's own matrix; the medium behind enters as
// baseF0 (0 for air: a soap bubble), as MeshPhysicalMaterial would pass it.
vec3 tfcFilmXyzOf(float thicknessNm, float cosIncidence, bool fromInside) {
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  vec3 baseF0 = vec3(IorToFresnel0(nc.x, 1.0));
  return inverse(XYZ_TO_REC709) * evalIridescence(na, uNFilm.x, cosIncidence, thicknessNm, baseF0);
}
#endif

vec3 tfcFilmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
#ifdef TFC_OPAQUE_INSIDE
  if (fromInside) return vec3(0.0);
#endif
  return tfcFilmXyzOf(thicknessNm, cosIncidence, fromInside);
}

#endif

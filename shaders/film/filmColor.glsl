// The film's XYZ at a thickness and cos θ_i, by the method TFC_FILM_MODE selects:
//   0 exact: the binned spectral integral per fragment;  1 table: one filtered lookup;
//   2 fourier: the Airy series per fragment (airySeries.glsl; by bins where it has no real path or
//     needs more than TFC_AIRY_SERIES_MAX_ORDERS terms);
//   3 three.js's iridescence (Belcour–Barla, `evalIridescence`), the benchmark's peer.
// TFC_DISPERSIVE: the film's index depends on λ (filmIndex.glsl); exact and fourier then take the
// dispersive bins, the table is filled from them, and uNFilm is n_b at the sodium D line (the peer's).
// fromInside swaps the outer and inner media (the far wall seen through the bubble).
#ifndef THIN_FILM_COLOR
#define THIN_FILM_COLOR

uniform float uNOutside;
uniform float uNFilm;
uniform float uNInside;

#if TFC_FILM_MODE == 0
#include "binnedIntegration.glsl"

vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  float na = fromInside ? uNInside : uNOutside;
  float nc = fromInside ? uNOutside : uNInside;
#ifdef TFC_DISPERSIVE
  return dispersiveBinnedXyz(na, nc, thicknessNm, cosIncidence, 0);
#else
  return binnedXyz(filmOptics(na, uNFilm, nc, thicknessNm, cosIncidence), 0.0);
#endif
}
#elif TFC_FILM_MODE == 1
#include "filmTableLayout.glsl"
uniform sampler2D uFilmTable;
uniform float uTableMaxThicknessNm;

vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  // Texel centres sit at the ends of the ranges (docs/gpu.md#texel-centres: otherwise visibly off).
  vec2 uv = filmTableUv(thicknessNm, cosIncidence, uTableMaxThicknessNm);
  // The grid may fill only the texture's lower left corner (a coarse table, FilmTable).
  vec2 size = vec2(textureSize(uFilmTable, 0));
  float rowOffset = fromInside ? uFilmTableRows : 0.0;
  vec2 texel = vec2(uv.x * (uFilmTableWidth - 1.0), rowOffset + uv.y * (uFilmTableRows - 1.0)) + 0.5;
  return texture(uFilmTable, texel / size).xyz;
}
#elif TFC_FILM_MODE == 2
#include "airySeries.glsl"
#include "binnedIntegration.glsl"

vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  float na = fromInside ? uNInside : uNOutside;
  float nc = fromInside ? uNOutside : uNInside;
#ifdef TFC_DISPERSIVE
  // A dispersive film has no series in x alone (docs/physics.md#a-dispersive-film): the bins take it.
  return dispersiveBinnedXyz(na, nc, thicknessNm, cosIncidence, 0);
#else
  FilmOptics o = filmOptics(na, uNFilm, nc, thicknessNm, cosIncidence);
  AirySeriesTerms t[TFC_FILM_CHANNELS];
  airySeriesTermsOf(o, t);
  float x = o.opticalPathNm.x;
  return o.opticalPathNm.y == 0.0 && (TFC_AIRY_SERIES_TRUNCATED == 1 || airySeriesConvergesAt(t, x)) ? airySeriesSum(t, x) : binnedXyz(o, 0.0);
#endif
}
#else
#define USE_IRIDESCENCE
#include <common>
#include <iridescence_fragment>

// Its Rec.709 reflectance back to XYZ with the chunk's own matrix; the medium behind enters as
// baseF0 (0 for air: a soap bubble), as MeshPhysicalMaterial would pass it.
vec3 filmXyz(float thicknessNm, float cosIncidence, bool fromInside) {
  float na = fromInside ? uNInside : uNOutside;
  float nc = fromInside ? uNOutside : uNInside;
  vec3 baseF0 = vec3(IorToFresnel0(nc, 1.0));
  return inverse(XYZ_TO_REC709) * evalIridescence(na, uNFilm, cosIncidence, thicknessNm, baseF0);
}
#endif

#endif

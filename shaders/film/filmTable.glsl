// The table of film XYZ over (thickness, cos θ_i), uFilmTableWidth x 2 uFilmTableRows texels:
// the lower half for light arriving from outside (n_a = uNOutside), the upper half from inside
// (media swapped: the far wall of the bubble). Its grid: filmTableGrid.glsl; texel positions: filmTableLayout.glsl.
// Filled by TFC_TABLE_FILL: 0 the binned integral, each texel averaged over its thickness cell so
// fringes finer than a cell do not alias; 1 the Airy series (airySeries.glsl) at the texel's film,
// or the bins where the series has no real path or needs too many terms, and for a line source,
// whose lines the bins sum directly (binnedIntegration.glsl), each averaged over the texel's cell. The series' C0, B, q
// depend on the row only: uAirySeriesRows holds them per row (src/film/airySeriesRows.ts,
// computed in float64), so a texel only sums the series.
// A dispersive film (TFC_DISPERSIVE) is filled from the dispersive bins at the texel's film, not
// averaged over its cell (with the bilinear lookup that would smooth twice; the `nFilm=water` rows'
// stress grid in docs/benchmarks.md measures it), their Fresnel terms per row and bin from
// uDispersiveRows (src/film/dispersiveRows.ts).
// A stack of films (TFC_FILM_LAYERS) is filled by its recursion per bin at the texel's thickness of
// its `d` layers (transferMatrix.glsl), as `exact` draws it per fragment.
// Drawn by src/film/filmTablePass.ts.
#ifdef TFC_DISPERSIVE
#define TFC_DISPERSIVE_ROWS 1
#endif
#include "binnedIntegration.glsl"
#include "airySeries.glsl"
#include "filmTableGrid.glsl"
#include "filmTableLayout.glsl"
#include "filmMedia.glsl"
#ifdef TFC_FILM_LAYERS
#include "transferMatrix.glsl"
#endif

#if TFC_TABLE_FILL == TFC_TABLE_FILL_SERIES
#include "texelRecord.glsl"
// Row y: a record of src/film/airySeriesRows.ts's AIRY_ROW, read by its names: C0, B, q of each
// channel, the path per nm of thickness (2 n_b cos θ_r) and 1 where it is real (0: an evanescent
// film, no series).
uniform sampler2D uAirySeriesRows;

bool tfcRowSeries(int y, out AirySeriesTerms t[TFC_FILM_CHANNELS], out float pathPerNm) {
  vec4 r[TFC_AIRY_ROW_TEXELS];
  for (int i = 0; i < TFC_AIRY_ROW_TEXELS; i++) r[i] = texelFetch(uAirySeriesRows, ivec2(i, y), 0);
  t[0] = AirySeriesTerms(TFC_RECORD_FLOAT(r, TFC_AIRY_ROW_C0_0), TFC_RECORD_VEC2(r, TFC_AIRY_ROW_B_0), TFC_RECORD_VEC2(r, TFC_AIRY_ROW_Q_0));
#ifdef TFC_BOTH_CHANNELS
  t[1] = AirySeriesTerms(TFC_RECORD_FLOAT(r, TFC_AIRY_ROW_C0_1), TFC_RECORD_VEC2(r, TFC_AIRY_ROW_B_1), TFC_RECORD_VEC2(r, TFC_AIRY_ROW_Q_1));
#endif
  pathPerNm = TFC_RECORD_FLOAT(r, TFC_AIRY_ROW_PATH_PER_NM);
  return TFC_RECORD_FLOAT(r, TFC_AIRY_ROW_REAL_PATH) == 1.0;
}
#endif

// What a texel holds: the film's XYZ, or with TFC_ENVIRONMENT_MATRIX its environment matrix, column j
// in plane j (a target of three textures, written at once: each bin's R serves all three).
layout(location = 0) out highp vec4 tfcTablePlane0;
#ifdef TFC_ENVIRONMENT_MATRIX
layout(location = 1) out highp vec4 tfcTablePlane1;
layout(location = 2) out highp vec4 tfcTablePlane2;
#endif
void tfcWriteTexel(TFC_FILM_COLOR c) {
#ifdef TFC_ENVIRONMENT_MATRIX
  tfcTablePlane0 = vec4(c[0], 1.0);
  tfcTablePlane1 = vec4(c[1], 1.0);
  tfcTablePlane2 = vec4(c[2], 1.0);
#else
  tfcTablePlane0 = vec4(c, 1.0);
#endif
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int rows = int(uFilmTableRows);
  bool fromInside = texel.y >= rows;
  int row = fromInside ? texel.y - rows : texel.y;
  float u = float(texel.x) / (uFilmTableWidth - 1.0);
  float thicknessNm = tfcFilmTableThicknessNm(u, uTableMaxThicknessNm);
  float cellNm = tfcFilmTableThicknessSlopeNm(u, uTableMaxThicknessNm) / (uFilmTableWidth - 1.0);
  float cosIncidence = tfcFilmTableCosIncidence(float(row) / (uFilmTableRows - 1.0));
#ifdef TFC_OPAQUE_INSIDE
  // No light reaches the film from an opaque inside: the upper half stays black (never looked up).
  if (fromInside) {
    tfcWriteTexel(TFC_FILM_COLOR(0.0));
    return;
  }
#endif
#ifdef TFC_FILM_LAYERS
  tfcWriteTexel(tfcLayersBinnedXyz(uNOutside, fromInside, thicknessNm, cosIncidence));
  return;
#endif
#if TFC_TABLE_FILL == TFC_TABLE_FILL_SERIES && !defined(TFC_DISPERSIVE)
  AirySeriesTerms terms[TFC_FILM_CHANNELS];
  float pathPerNm;
  // At thickness 0 filmOptics decides (the bare interface, or the paper mode's eq 13), as in the reference.
  if (uLightLineCount == 0 && thicknessNm > 0.0 && tfcRowSeries(texel.y, terms, pathPerNm) && tfcAirySeriesConvergesAt(terms, pathPerNm * thicknessNm)) {
    tfcWriteTexel(tfcAirySeriesSum(terms, pathPerNm * thicknessNm));
    return;
  }
#endif
#ifdef TFC_DISPERSIVE
  tfcWriteTexel(tfcDispersiveBinnedXyz(fromInside, thicknessNm, cosIncidence, texel.y));
#else
  float na;
  vec2 nc;
  tfcFilmSides(fromInside, na, nc);
  FilmOptics o = tfcFilmOptics(na, uNFilm, nc, thicknessNm, cosIncidence);
  // Phase half-width of a cell at λ: 2π · Re(2 ñ_b cos θ_r) · (cell / 2) / λ = 2π · Re(Δ per nm) · cell / (2λ).
  float perNmPath = thicknessNm > 0.0 ? o.opticalPathNm.x / thicknessNm : tfcFilmPathPerNm(uNFilm, na, cosIncidence);
  tfcWriteTexel(tfcBinnedXyz(o, 3.141592653589793 * perNmPath * cellNm));
#endif
}

// The table of film XYZ over (thickness, cos θ_i), uFilmTableWidth x 2 * FILM_TABLE_ROWS texels:
// the lower half for light arriving from outside (n_a = uNOutside), the upper half from inside
// (media swapped: the far wall of the bubble). Texel positions: filmTableLayout.glsl.
// Filled by TABLE_FILL: 0 the binned integral, each texel averaged over its thickness cell so
// fringes finer than a cell do not alias; 1 the Airy series (airySeries.glsl) at the texel's film,
// or the bins where the series has no real path or needs too many terms.
// Built by src/render/filmTable.ts.
#include "spectralIntegration.glsl"
#include "airySeries.glsl"
#include "filmTableLayout.glsl"

uniform float uNOutside;
uniform float uNFilm;
uniform float uNInside;
uniform float uTableMaxThicknessNm;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  bool fromInside = texel.y >= FILM_TABLE_ROWS;
  int row = fromInside ? texel.y - FILM_TABLE_ROWS : texel.y;
  float u = float(texel.x) / (uFilmTableWidth - 1.0);
  float thicknessNm = filmTableThicknessNm(u, uTableMaxThicknessNm);
  float cellNm = filmTableThicknessSlopeNm(u, uTableMaxThicknessNm) / (uFilmTableWidth - 1.0);
  float cosIncidence = filmTableCosIncidence(float(row) / float(FILM_TABLE_ROWS - 1));
  float na = fromInside ? uNInside : uNOutside;
  float nc = fromInside ? uNOutside : uNInside;
  FilmOptics o = filmOptics(na, uNFilm, nc, thicknessNm, cosIncidence);
#if TABLE_FILL == 1
  if (o.opticalPathNm.y == 0.0 && airySeriesConverges(o)) {
    gl_FragColor = vec4(airySeriesXyz(o), 1.0);
    return;
  }
#endif
  // Phase half-width of a cell at λ: 2π · 2 n_b cos θ_r · (cell / 2) / λ = 2π · Re(Δ per nm) · cell / (2λ).
  float perNmPath = thicknessNm > 0.0 ? o.opticalPathNm.x / thicknessNm : 2.0 * uNFilm * refractedCos(uNFilm, na, cosIncidence).x;
  gl_FragColor = vec4(binnedXyz(o, 3.141592653589793 * perNmPath * cellNm), 1.0);
}

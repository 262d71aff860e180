// Where (thickness, cos θ_i) sit in the film table: one mapping for the table pass (filmTable.glsl)
// and the lookup (the `table` method, shaders/methods/tableMethod.glsl). u, v in [0, 1] run from
// the first to the last texel centre:
//   d = max · u^TFC_FILM_TABLE_THICKNESS_POWER,   cos θ_i = v^TFC_FILM_TABLE_COS_POWER.
// Powers above 1 spend texels on thin films and grazing light. The powers (defines) come from
// src/settings/filmTableLayout.ts; the grid's size (uniforms) is declared by filmTableGrid.glsl.
#ifndef THIN_FILM_TABLE_LAYOUT
#define THIN_FILM_TABLE_LAYOUT

float tfcFilmTableThicknessNm(float u, float maxThicknessNm) {
  return maxThicknessNm * pow(u, float(TFC_FILM_TABLE_THICKNESS_POWER));
}

// d d / d u: a texel's thickness cell is this × 1 / (width - 1) of a grid `width` texels wide.
float tfcFilmTableThicknessSlopeNm(float u, float maxThicknessNm) {
  float power = float(TFC_FILM_TABLE_THICKNESS_POWER);
  return maxThicknessNm * power * pow(max(u, 1e-6), power - 1.0); // pow(0, 0) is undefined in GLSL
}

float tfcFilmTableCosIncidence(float v) {
  return pow(v, float(TFC_FILM_TABLE_COS_POWER));
}

// The inverse of both maps: (u, v) for a film, clamped to the table.
vec2 tfcFilmTableUv(float thicknessNm, float cosIncidence, float maxThicknessNm) {
  float u = pow(clamp(thicknessNm / maxThicknessNm, 0.0, 1.0), 1.0 / float(TFC_FILM_TABLE_THICKNESS_POWER));
  float v = pow(clamp(cosIncidence, 0.0, 1.0), 1.0 / float(TFC_FILM_TABLE_COS_POWER));
  return vec2(u, v);
}

#endif

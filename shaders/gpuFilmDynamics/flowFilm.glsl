// The film's texel, a FLOW_FILM record (src/gpuFilmDynamics/flowTexels.ts): η and Γ (in η0, Γ0), whether the
// cell is intact, and whether it gave way this step (the mark the rupture passes count). The padded
// film holds the same record per padded texel, so a bilinear sample of it decodes alike.
#ifndef THIN_FILM_FLOW_FILM
#define THIN_FILM_FLOW_FILM
#include "texelRecord.glsl"

struct TfcFilm {
  float eta;
  float gamma;
  bool intact;
  bool marked;
};

TfcFilm tfcFilm(vec4 texel) {
  return TfcFilm(
    TFC_TEXEL_FLOAT(texel, TFC_FLOW_FILM_ETA),
    TFC_TEXEL_FLOAT(texel, TFC_FLOW_FILM_GAMMA),
    TFC_TEXEL_FLOAT(texel, TFC_FLOW_FILM_INTACT) != 0.0,
    TFC_TEXEL_FLOAT(texel, TFC_FLOW_FILM_MARK) != 0.0
  );
}

vec4 tfcFilmTexel(TfcFilm film) {
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_FLOW_FILM_ETA, film.eta);
  TFC_SET_TEXEL_FLOAT(texel, TFC_FLOW_FILM_GAMMA, film.gamma);
  TFC_SET_TEXEL_FLOAT(texel, TFC_FLOW_FILM_INTACT, film.intact ? 1.0 : 0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_FLOW_FILM_MARK, film.marked ? 1.0 : 0.0);
  return texel;
}

/** The film of the texel `texel` of `film` (a cell atlas). */
TfcFilm tfcFilmAt(sampler2D film, ivec2 texel) { return tfcFilm(texelFetch(film, texel, 0)); }
#endif

// The film's and the inside's indices ñ(λ) = n + ik where either depends on λ (TFC_DISPERSIVE):
// uMediaKnots holds them at TFC_MEDIA_KNOTS wavelengths every TFC_MEDIA_STEP_NM from
// TFC_MEDIA_FIRST_NM, one vec4 per knot (film n, k, inside n, k), computed in float64 by
// src/physics/medium.ts (mediumIndexAt) and taken as linear between knots. Mirrors mediumIndexAt;
// set by src/film/filmMedia.ts.
#ifndef THIN_FILM_MEDIUM
#define THIN_FILM_MEDIUM

uniform vec4 uMediaKnots[TFC_MEDIA_KNOTS];

// (film n, k, inside n, k) at λ.
vec4 tfcMediaAt(float lambdaNm) {
  float pos = clamp((lambdaNm - float(TFC_MEDIA_FIRST_NM)) / float(TFC_MEDIA_STEP_NM), 0.0, float(TFC_MEDIA_KNOTS - 1));
  int i = min(int(pos), TFC_MEDIA_KNOTS - 2);
  return mix(uMediaKnots[i], uMediaKnots[i + 1], pos - float(i));
}

#endif

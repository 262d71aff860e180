// GPU pass 8 of the step (mirrors src/physics/filmDynamics/ruptureFilm.ts): rupture and Taylor–Culick
// bursting, as five draws. (1) tfcRuptureFilm, a cell-atlas pass: an intact cell whose film is at
// or below the rupture thickness, or whose Γ would bring the tension to 0, loses its film, and is
// marked where no open hole holds it: a hole opens there. (2) tfcRuptureRows counts the marks of
// each row (face, j) of n cells, 6n RUPTURE_ROW texels in cell order. (3) tfcOpenHoles gives the
// free slots of the hole table (filmHoles.glsl) the marked cells in cell order, as the twin's loop
// over cells pushes them (or the puncture uPuncture). (4) tfcGrowRims advances each ray by
// Δt·V, V = rimSpeedFactor·√(2γ/(ρh)) of the padded film sampled uRimLead ahead of the rim. (5)
// tfcEmptyHoles removes the film of every cell inside an open hole.
#include "cubeSphereGrid.glsl"
#include "cubeSphereSampler.glsl"
#include "renewFilm.glsl"
#include "filmStep_pars.glsl"
uniform float uRuptureEta;
uniform float uRuptureGamma;

vec4 tfcRuptureFilm() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  TfcFilm film = tfcFilmAt(uFilm, texel);
  film.marked = false;
  if (!film.intact || (film.eta > uRuptureEta && film.gamma < uRuptureGamma)) return tfcFilmTexel(film);
  bool held = tfcInsideAnyHole(uHoles, tfcCell(tfcCellAt(texel)).center);
  return tfcFilmTexel(TfcFilm(0.0, 0.0, false, !held));
}

/** The marks of row r = face·n + j: cells r·n to r·n + n − 1. A 6n × 1 pass. */
vec4 tfcRuptureRows() {
  int first = int(gl_FragCoord.x) * uFlowGridN;
  float count = 0.0;
  for (int i = 0; i < uFlowGridN; i++) count += tfcFilmAt(uFilm, tfcCellTexel(first + i)).marked ? 1.0 : 0.0;
  vec4 row = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(row, TFC_RUPTURE_ROW_MARKS, count);
  return row;
}

uniform sampler2D uRuptureRows;
/** A direction to puncture the film at, when uPunctured is 1 (then no marked cell opens a hole). */
uniform vec3 uPuncture;
uniform float uPunctured;

/** The marks of row r. */
int tfcRowMarks(int r) {
  vec4 row = texelFetch(uRuptureRows, ivec2(r, 0), 0);
  return tfcIndex(TFC_TEXEL_FLOAT(row, TFC_RUPTURE_ROW_MARKS));
}

/** Whether there is an m-th marked cell in cell order (m from 0), and its centre. */
bool tfcMarkedCell(int m, out vec3 center) {
  int n = uFlowGridN;
  for (int r = 0; r < 6 * n; r++) {
    int count = tfcRowMarks(r);
    if (m >= count) {
      m -= count;
      continue;
    }
    for (int i = 0; i < n; i++) {
      int c = r * n + i;
      if (!tfcFilmAt(uFilm, tfcCellTexel(c)).marked) continue;
      if (m == 0) {
        center = tfcCell(c).center;
        return true;
      }
      m--;
    }
  }
  return false;
}

/** Whether the free slot `m` of this step (m from 0) takes a hole, and at which direction: the puncture's, or the m-th marked cell's. */
bool tfcHoleToOpen(int m, out vec3 at) {
  at = uPuncture;
  return uPunctured != 0.0 ? m == 0 : tfcMarkedCell(m, at);
}

/** openHole for the free slots, filled in order (a hole-table pass). */
vec4 tfcOpenHoles() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 old = texelFetch(uHoles, texel, 0);
  if (tfcRenewing()) return vec4(0.0);
  if (texel.x < TFC_HOLE_RAYS || tfcReadHole(uHoles, texel.y).open) return old;
  int open = 0;
  for (int s = 0; s < TFC_MAX_HOLES; s++) open += tfcReadHole(uHoles, s).open ? 1 : 0;
  vec3 at;
  return tfcHoleToOpen(texel.y - open, at) ? tfcHoleTexel(tfcNewHole(at), texel.x) : old;
}

uniform sampler2D uPaddedFilm;
/** rimSpeedFactor·√(2γ_a/(ρh̄)) in U: the rim's speed in film of η = 1 and Γ = 0. */
uniform float uRimSpeed;
/** The thinnest film a speed is computed for, in η0. */
uniform float uRimEtaFloor;
/** How far ahead of the rim the film is sampled (radians): 1.5 cells, so the taps miss the emptied ones. */
uniform float uRimLead;

/** growRims: ray k of hole s a step further, at the Taylor–Culick speed of the film ahead (a hole-table pass). */
vec4 tfcGrowRims() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 old = texelFetch(uHoles, texel, 0);
  TfcHole h = tfcReadHole(uHoles, texel.y);
  if (texel.x >= TFC_HOLE_RAYS || !h.open) return old;
  float radius = TFC_TEXEL_FLOAT(old, TFC_HOLE_RAY_RADIUS);
  if (radius >= TFC_HOLE_PI) return old;
  float psi = 2.0 * TFC_HOLE_PI * float(texel.x) / float(TFC_HOLE_RAYS);
  TfcFilm ahead = tfcFilm(tfcSamplePadded(uPaddedFilm, tfcPointOnRay(h, psi, min(TFC_HOLE_PI, radius + uRimLead))));
  // γ/γ_a = 1 − R̄TΓ0Γ/γ_a = 1 − Γ/uRuptureGamma (the Γ at which the tension reaches 0).
  float speed = uRimSpeed * sqrt(max(0.0, 1.0 - ahead.gamma / uRuptureGamma) / max(uRimEtaFloor, ahead.eta));
  return tfcRayTexel(min(TFC_HOLE_PI, radius + speed * uDt));
}

uniform sampler2D uStartFilm;

/** The film after the rims: no film inside an open hole, the marks cleared (or, renewing, the start). */
vec4 tfcEmptyHoles() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  if (tfcRenewing()) return texelFetch(uStartFilm, texel, 0);
  TfcFilm film = tfcFilmAt(uFilm, texel);
  film.marked = false;
  if (film.intact && tfcInsideAnyHole(uHoles, tfcCell(tfcCellAt(texel)).center)) return tfcFilmTexel(TfcFilm(0.0, 0.0, false, false));
  return tfcFilmTexel(film);
}

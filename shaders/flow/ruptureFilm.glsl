// GPU pass 8 of the step (mirrors src/physics/flow/ruptureFilm.ts): rupture and Taylor–Culick
// bursting, as five draws. (1) tfcRuptureFilm, a cell-atlas pass: an intact cell whose film is at
// or below the rupture thickness, or whose Γ would bring the tension to 0, loses its film, and is
// marked (a = 1) where no open hole holds it: a hole opens there. (2) tfcRuptureRows counts the
// marks of each row (face, j) of n cells, 6n texels in cell order. (3) tfcOpenHoles gives the free
// slots of the hole table (filmHoles.glsl) the marked cells in cell order, as the twin's loop over
// cells pushes them (or the puncture uPuncture, with w = 1). (4) tfcGrowRims advances each ray by
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
  vec4 film = texelFetch(uFilm, texel, 0);
  if (film.b == 0.0 || (film.r > uRuptureEta && film.g < uRuptureGamma)) return vec4(film.rgb, 0.0);
  bool held = tfcInsideAnyHole(uHoles, tfcCellGeometry(tfcCellAt(texel)).xyz);
  return vec4(0.0, 0.0, 0.0, held ? 0.0 : 1.0);
}

/** The marks of row r = face·n + j: cells r·n to r·n + n − 1. A 6n × 1 pass. */
vec4 tfcRuptureRows() {
  int first = int(gl_FragCoord.x) * uFlowGridN;
  float count = 0.0;
  for (int i = 0; i < uFlowGridN; i++) count += texelFetch(uFilm, tfcCellTexel(first + i), 0).a;
  return vec4(count, 0.0, 0.0, 0.0);
}

uniform sampler2D uRuptureRows;
/** xyz: a direction to puncture the film at, when w = 1 (then no marked cell opens a hole). */
uniform vec4 uPuncture;

/** The centre of the m-th marked cell in cell order (m from 0), w = 1; w = 0 if there are not so many. */
vec4 tfcMarkedCell(int m) {
  int n = uFlowGridN;
  for (int r = 0; r < 6 * n; r++) {
    int count = tfcIndex(texelFetch(uRuptureRows, ivec2(r, 0), 0).r);
    if (m >= count) {
      m -= count;
      continue;
    }
    for (int i = 0; i < n; i++) {
      int c = r * n + i;
      if (texelFetch(uFilm, tfcCellTexel(c), 0).a == 0.0) continue;
      if (m == 0) return vec4(tfcCellGeometry(c).xyz, 1.0);
      m--;
    }
  }
  return vec4(0.0);
}

/** openHole for the free slots, filled in order (a hole-table pass). */
vec4 tfcOpenHoles() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 old = texelFetch(uHoles, texel, 0);
  if (tfcRenewing()) return vec4(0.0);
  if (texel.x < TFC_HOLE_RAYS || tfcReadHole(uHoles, texel.y).open) return old;
  int open = 0;
  for (int s = 0; s < TFC_MAX_HOLES; s++) open += tfcReadHole(uHoles, s).open ? 1 : 0;
  int m = texel.y - open;
  vec4 at = uPuncture.w != 0.0 ? (m == 0 ? uPuncture : vec4(0.0)) : tfcMarkedCell(m);
  return at.w != 0.0 ? tfcHoleTexel(tfcNewHole(at.xyz), texel.x) : old;
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
  if (texel.x >= TFC_HOLE_RAYS || !h.open || old.r >= TFC_HOLE_PI) return old;
  float psi = 2.0 * TFC_HOLE_PI * float(texel.x) / float(TFC_HOLE_RAYS);
  vec4 ahead = tfcSamplePadded(uPaddedFilm, tfcPointOnRay(h, psi, min(TFC_HOLE_PI, old.r + uRimLead)));
  // γ/γ_a = 1 − R̄TΓ0Γ/γ_a = 1 − Γ/uRuptureGamma (the Γ at which the tension reaches 0).
  float speed = uRimSpeed * sqrt(max(0.0, 1.0 - ahead.g / uRuptureGamma) / max(uRimEtaFloor, ahead.r));
  return vec4(min(TFC_HOLE_PI, old.r + speed * uDt), 0.0, 0.0, 0.0);
}

uniform sampler2D uStartFilm;

/** The film after the rims: no film inside an open hole, the marks cleared (or, renewing, the start). */
vec4 tfcEmptyHoles() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  if (tfcRenewing()) return vec4(texelFetch(uStartFilm, texel, 0).rg, 1.0, 0.0);
  vec4 film = texelFetch(uFilm, texel, 0);
  if (film.b != 0.0 && tfcInsideAnyHole(uHoles, tfcCellGeometry(tfcCellAt(texel)).xyz)) return vec4(0.0);
  return vec4(film.rgb, 0.0);
}

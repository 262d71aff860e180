// GPU pass 3 of the step (mirrors src/physics/filmDynamics/predictEdgeVelocity.ts): at each edge the
// velocity traced back along the great circle for Δt (semi-Lagrangian, sampled from the padded cell
// velocity and parallel-transported to the edge), then the semi-implicit force step of eq. (17)
//   u* = (η_e u_adv/Δt + η_e g_e + Cr u_air) / (η_e/Δt + Cr),   c_e = M/(η_e/Δt + Cr),
// u_air the wind's air at the surface (its direction the step's) plus a blow's,
// η_e the logarithmic mean. Edges beside a ruptured cell are closed. An edge-atlas pass: a
// PREDICTION record (u*, c_e) per edge.
#include "cubeSphereGrid.glsl"
#include "cubeSphereSampler.glsl"
#include "logarithmicMean.glsl"
#include "filmStep_pars.glsl"
uniform sampler2D uCellVelocity;
uniform sampler2D uPaddedCellVelocity;
uniform float uAirFriction;
uniform float uGravity;
uniform float uMarangoni;
/**
 * The air at the surface: the x and y components of WIND_SURFACE_FACTOR × the wind (in U) at the
 * step's direction (src/physics/filmDynamics/windDirection.ts), set before each step.
 */
uniform vec2 uSurfaceWind;
/**
 * A blow, the app's interaction (the twin has none): air at uBlowVelocity (in U, tangent at
 * uBlowCenter) in a Gaussian patch exp(−(1 − x·c)/w²), w = TFC_BLOW_WIDTH_RAD; 0 when still.
 */
uniform vec3 uBlowCenter;
uniform vec3 uBlowVelocity;

/** A cell's velocity in a texel of the cell velocity (or of its padded atlas, sampled). */
vec3 tfcCellVelocity(vec4 texel) { return TFC_TEXEL_VEC3(texel, TFC_CELL_VELOCITY_U); }

/** An edge's prediction texel: u* and c_e. */
vec4 tfcPredictionTexel(float predicted, float coefficient) {
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(texel, TFC_PREDICTION_U_STAR, predicted);
  TFC_SET_TEXEL_FLOAT(texel, TFC_PREDICTION_MARANGONI, coefficient);
  return texel;
}

vec4 tfcPredictEdgeVelocity() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  TfcEdgeCells cells = tfcEdgeCells(e);
  int ca = cells.a;
  int cb = cells.b;
  TfcFilm filmA = tfcFilmAt(uFilm, tfcCellTexel(ca));
  TfcFilm filmB = tfcFilmAt(uFilm, tfcCellTexel(cb));
  if (!filmA.intact || !filmB.intact) return tfcPredictionTexel(0.0, 0.0);
  vec3 m = tfcEdgeMid(e);
  TfcEdgeNormal normal = tfcEdgeNormal(e);
  vec3 n = normal.normal;
  // The velocity at the midpoint: the mean of the two cells', in the tangent plane there.
  vec3 w = 0.5 * (tfcCellVelocity(texelFetch(uCellVelocity, tfcCellTexel(ca), 0)) + tfcCellVelocity(texelFetch(uCellVelocity, tfcCellTexel(cb), 0)));
  w -= dot(w, m) * m;
  float speed = length(w);
  float advected;
  if (speed * uDt > 0.0) {
    float s = speed * uDt;
    vec3 t = w / speed;
    float cs = cos(s);
    float sn = sin(s);
    vec3 b = tfcCellVelocity(tfcSamplePadded(uPaddedCellVelocity, cs * m - sn * t));
    // Parallel transport along the great circle: the component along the path becomes the one
    // along t here; the one along k = m × t is kept.
    vec3 k = cross(m, t);
    advected = dot(b, sn * m + cs * t) * dot(t, n) + dot(b, k) * dot(k, n);
  } else {
    advected = dot(w, n);
  }
  float etaEdge = tfcLogarithmicMean(filmA.eta, filmB.eta);
  float gravityAlongNormal = -uGravity * normal.zSlope;
  float denominator = etaEdge / uDt + uAirFriction;
  float blow = exp(-(1.0 - dot(m, uBlowCenter)) / (TFC_BLOW_WIDTH_RAD * TFC_BLOW_WIDTH_RAD)) * dot(uBlowVelocity, n);
  float air = dot(uSurfaceWind, n.xy) + blow;
  float predicted = (etaEdge * advected / uDt + etaEdge * gravityAlongNormal + uAirFriction * air) / denominator;
  return tfcPredictionTexel(predicted, uMarangoni / denominator);
}

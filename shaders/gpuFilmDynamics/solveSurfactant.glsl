// GPU pass 4–5 of the step (mirrors src/physics/filmDynamics/solveSurfactant.ts): the surfactant at the
// end of the step, implicit in the Marangoni term,
//   (A_c + Σ_e w_e) Γ'_c − Σ_e w_e Γ'_nb = A_c Γ_c − Δt Σ_e L_e (u*·n_out)_e Γ̄_e,  w_e = Δt L_e Γ̄_e c_e/d_e,
// solved for the increment δ = Γ' − Γ from δ = 0, as cell-atlas passes: the weights (one per
// side), the right side b − AΓ (from the fluxes and the differences of Γ) and the diagonal, and the
// schedule's Chebyshev-accelerated Jacobi sweeps (src/physics/filmDynamics/chebyshevSchedule.ts); then an
// edge-atlas pass u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e. The weights, the system and a sweep are
// records of src/gpuFilmDynamics/flowTexels.ts (SURFACTANT_WEIGHTS, SURFACTANT_SYSTEM, SURFACTANT_SWEEP).
#include "cubeSphereGrid.glsl"
#include "filmStep_pars.glsl"
uniform sampler2D uPrediction;

/** Edge e's u* and c_e. */
void tfcPrediction(int e, out float predicted, out float coefficient) {
  vec4 prediction = texelFetch(uPrediction, tfcEdgeTexel(e), 0);
  predicted = TFC_TEXEL_FLOAT(prediction, TFC_PREDICTION_U_STAR);
  coefficient = TFC_TEXEL_FLOAT(prediction, TFC_PREDICTION_MARANGONI);
}

/** Γ of cell c. */
float tfcGammaOf(int c) { return tfcFilmAt(uFilm, tfcCellTexel(c)).gamma; }

/** Γ̄_e of the side s of cell c whose neighbour is nb. */
float tfcMeanGamma(float gammaC, int nb) { return 0.5 * (gammaC + tfcGammaOf(nb)); }

/** The weights w_e of the cell's 4 sides. */
vec4 tfcSurfactantWeights() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  float gammaC = tfcGammaOf(c);
  vec4 edges = tfcCellEdges(c);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    TfcEdgeCells cells = tfcEdgeCells(e);
    float predicted, coefficient;
    tfcPrediction(e, predicted, coefficient);
    weight[s] = uDt * cells.length * tfcMeanGamma(gammaC, tfcIndex(neighbors[s])) * coefficient / cells.distance;
  }
  vec4 texel = vec4(0.0);
  TFC_SET_TEXEL_VEC4(texel, TFC_SURFACTANT_WEIGHTS_SIDES, weight);
  return texel;
}

uniform sampler2D uSurfactantWeights;

/** The weights w_e of the 4 sides of the cell at `texel`, side s in [s]. */
vec4 tfcWeightsAt(ivec2 texel) {
  vec4 weights = texelFetch(uSurfactantWeights, texel, 0);
  return TFC_TEXEL_VEC4(weights, TFC_SURFACTANT_WEIGHTS_SIDES);
}

/** The right side b − AΓ = −Σ_e [Δt L_e (u*·n_out)_e Γ̄_e + w_e (Γ_c − Γ_nb)] and the diagonal. */
vec4 tfcSurfactantSystem() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  float area = tfcCell(c).area;
  float gammaC = tfcGammaOf(c);
  vec4 edges = tfcCellEdges(c);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = tfcWeightsAt(tfcCellTexel(c));
  float b = 0.0;
  float d = area;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    float gammaNb = tfcGammaOf(tfcIndex(neighbors[s]));
    float predicted, coefficient;
    tfcPrediction(e, predicted, coefficient);
    b -= uDt * tfcEdgeCells(e).length * sign(edges[s]) * predicted * 0.5 * (gammaC + gammaNb) + weight[s] * (gammaC - gammaNb);
    d += weight[s];
  }
  vec4 system = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(system, TFC_SURFACTANT_SYSTEM_RHS, b);
  TFC_SET_TEXEL_FLOAT(system, TFC_SURFACTANT_SYSTEM_DIAGONAL, d);
  return system;
}

uniform sampler2D uSurfactantRhs;
uniform sampler2D uGuess;
/**
 * The one-hot masks of the fields of uGuess that hold x_k and x_{k−1} (a SURFACTANT_SWEEP's X and
 * PREVIOUS_X, set from its offsets; zero for the first sweep's x_0 = 0).
 */
uniform vec4 uGuessChannel;
uniform vec4 uPreviousGuessChannel;
/** This sweep's coefficients: x_{k+1} = x_k + momentum (x_k − x_{k−1}) + step D⁻¹(b − Ax_k). */
uniform float uChebyshevMomentum;
uniform float uChebyshevStep;

/** One Chebyshev-accelerated Jacobi sweep: x_{k+1}, and the x_k it read. */
vec4 tfcChebyshevSweep() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int c = tfcCellAt(texel);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = tfcWeightsAt(texel);
  vec4 system = texelFetch(uSurfactantRhs, texel, 0);
  float diagonal = TFC_TEXEL_FLOAT(system, TFC_SURFACTANT_SYSTEM_DIAGONAL);
  float sum = TFC_TEXEL_FLOAT(system, TFC_SURFACTANT_SYSTEM_RHS);
  for (int s = 0; s < 4; s++) sum += weight[s] * dot(texelFetch(uGuess, tfcCellTexel(tfcIndex(neighbors[s])), 0), uGuessChannel);
  vec4 guess = texelFetch(uGuess, texel, 0);
  float x = dot(guess, uGuessChannel);
  float r = sum - diagonal * x;
  vec4 sweep = vec4(0.0);
  TFC_SET_TEXEL_FLOAT(sweep, TFC_SURFACTANT_SWEEP_X, x + uChebyshevMomentum * (x - dot(guess, uPreviousGuessChannel)) + uChebyshevStep * r / diagonal);
  TFC_SET_TEXEL_FLOAT(sweep, TFC_SURFACTANT_SWEEP_PREVIOUS_X, x);
  return sweep;
}

uniform sampler2D uSolvedGamma;

/** The solved increment δ of the cell at `texel`. */
float tfcIncrementAt(ivec2 texel) {
  vec4 sweep = texelFetch(uSolvedGamma, texel, 0);
  return TFC_TEXEL_FLOAT(sweep, TFC_SURFACTANT_SWEEP_X);
}

/** u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e with Γ' = Γ + δ (an edge-atlas pass). */
vec4 tfcCorrectEdgeVelocity() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  TfcEdgeCells cells = tfcEdgeCells(e);
  float predicted, coefficient;
  tfcPrediction(e, predicted, coefficient);
  ivec2 a = tfcCellTexel(cells.a);
  ivec2 b = tfcCellTexel(cells.b);
  float increment = tfcIncrementAt(b) - tfcIncrementAt(a);
  float slope = (tfcFilmAt(uFilm, b).gamma - tfcFilmAt(uFilm, a).gamma + increment) / cells.distance;
  return tfcEdgeVelocityTexel(predicted - coefficient * slope);
}

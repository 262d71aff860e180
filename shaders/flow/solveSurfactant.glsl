// GPU pass 4–5 of the step (mirrors src/physics/flow/solveSurfactant.ts): the surfactant at the
// end of the step, implicit in the Marangoni term,
//   (A_c + Σ_e w_e) Γ'_c − Σ_e w_e Γ'_nb = A_c Γ_c − Δt Σ_e L_e (u*·n_out)_e Γ̄_e,  w_e = Δt L_e Γ̄_e c_e/d_e,
// solved for the increment δ = Γ' − Γ from δ = 0, as cell-atlas passes: the weights (one per
// side), the right side b − AΓ (from the fluxes and the differences of Γ) and the diagonal, and the
// schedule's Chebyshev-accelerated Jacobi sweeps (src/physics/flow/chebyshevSchedule.ts; each also
// writes (b − Ax)² of the x it read, for the residual); then an edge-atlas pass
// u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e. The system's and a sweep's channels are named by
// src/flow/flowLayouts.ts (TFC_SURFACTANT_SYSTEM_*, TFC_SURFACTANT_SWEEP_*).
#include "cubeSphereGrid.glsl"
#include "filmStep_pars.glsl"
uniform sampler2D uPrediction;

/** Γ̄_e of the side s of cell c whose neighbour is nb. */
float tfcMeanGamma(float gammaC, int nb) { return 0.5 * (gammaC + texelFetch(uFilm, tfcCellTexel(nb), 0).g); }

/** The weights w_e of the cell's 4 sides. */
vec4 tfcSurfactantWeights() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  float gammaC = texelFetch(uFilm, tfcCellTexel(c), 0).g;
  vec4 edges = tfcCellEdges(c);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    vec4 cells = tfcEdgeCells(e);
    float coefficient = texelFetch(uPrediction, tfcEdgeTexel(e), 0).g;
    weight[s] = uDt * cells.z * tfcMeanGamma(gammaC, tfcIndex(neighbors[s])) * coefficient / cells.w;
  }
  return weight;
}

uniform sampler2D uSurfactantWeights;

/** The right side b − AΓ = −Σ_e [Δt L_e (u*·n_out)_e Γ̄_e + w_e (Γ_c − Γ_nb)] and the diagonal. */
vec4 tfcSurfactantSystem() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  float area = tfcCellGeometry(c).w;
  float gammaC = texelFetch(uFilm, tfcCellTexel(c), 0).g;
  vec4 edges = tfcCellEdges(c);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = texelFetch(uSurfactantWeights, tfcCellTexel(c), 0);
  float b = 0.0;
  float d = area;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    float gammaNb = texelFetch(uFilm, tfcCellTexel(tfcIndex(neighbors[s])), 0).g;
    b -= uDt * tfcEdgeCells(e).z * sign(edges[s]) * texelFetch(uPrediction, tfcEdgeTexel(e), 0).r * 0.5 * (gammaC + gammaNb) + weight[s] * (gammaC - gammaNb);
    d += weight[s];
  }
  vec4 system = vec4(0.0);
  system[TFC_SURFACTANT_SYSTEM_RHS_CHANNEL] = b;
  system[TFC_SURFACTANT_SYSTEM_DIAGONAL_CHANNEL] = d;
  return system;
}

uniform sampler2D uSurfactantRhs;
uniform sampler2D uGuess;
/** The one-hot masks of the channels of uGuess that hold x_k and x_{k−1} (a sweep's x and previous x; zero for the first sweep's x_0 = 0). */
uniform vec4 uGuessChannel;
uniform vec4 uPreviousGuessChannel;
/** This sweep's coefficients: x_{k+1} = x_k + momentum (x_k − x_{k−1}) + step D⁻¹(b − Ax_k). */
uniform float uChebyshevMomentum;
uniform float uChebyshevStep;

/** One Chebyshev-accelerated Jacobi sweep: x_{k+1}, x_k and (b − Ax_k)². */
vec4 tfcChebyshevSweep() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int c = tfcCellAt(texel);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = texelFetch(uSurfactantWeights, texel, 0);
  vec4 system = texelFetch(uSurfactantRhs, texel, 0);
  float diagonal = system[TFC_SURFACTANT_SYSTEM_DIAGONAL_CHANNEL];
  float sum = system[TFC_SURFACTANT_SYSTEM_RHS_CHANNEL];
  for (int s = 0; s < 4; s++) sum += weight[s] * dot(texelFetch(uGuess, tfcCellTexel(tfcIndex(neighbors[s])), 0), uGuessChannel);
  vec4 guess = texelFetch(uGuess, texel, 0);
  float x = dot(guess, uGuessChannel);
  float r = sum - diagonal * x;
  vec4 sweep = vec4(0.0);
  sweep[TFC_SURFACTANT_SWEEP_X_CHANNEL] = x + uChebyshevMomentum * (x - dot(guess, uPreviousGuessChannel)) + uChebyshevStep * r / diagonal;
  sweep[TFC_SURFACTANT_SWEEP_PREVIOUS_X_CHANNEL] = x;
  sweep[TFC_SURFACTANT_SWEEP_RESIDUAL_SQUARED_CHANNEL] = r * r;
  return sweep;
}

uniform sampler2D uSolvedGamma;

/** u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e with Γ' = Γ + δ (an edge-atlas pass). */
vec4 tfcCorrectEdgeVelocity() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  vec4 cells = tfcEdgeCells(e);
  vec2 prediction = texelFetch(uPrediction, tfcEdgeTexel(e), 0).rg;
  ivec2 a = tfcCellTexel(tfcIndex(cells.x));
  ivec2 b = tfcCellTexel(tfcIndex(cells.y));
  float increment = texelFetch(uSolvedGamma, b, 0)[TFC_SURFACTANT_SWEEP_X_CHANNEL] - texelFetch(uSolvedGamma, a, 0)[TFC_SURFACTANT_SWEEP_X_CHANNEL];
  float slope = (texelFetch(uFilm, b, 0).g - texelFetch(uFilm, a, 0).g + increment) / cells.w;
  return vec4(prediction.r - prediction.g * slope, 0.0, 0.0, 0.0);
}

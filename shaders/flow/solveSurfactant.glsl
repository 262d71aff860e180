// GPU pass 4–5 of the step (mirrors src/physics/flow/solveSurfactant.ts): the surfactant at the
// end of the step, implicit in the Marangoni term,
//   (A_c + Σ_e w_e) Γ'_c − Σ_e w_e Γ'_nb = A_c Γ_c − Δt Σ_e L_e (u*·n_out)_e Γ̄_e,  w_e = Δt L_e Γ̄_e c_e/d_e,
// as cell-atlas passes: the weights (one per side), the right side and diagonal, and
// SURFACTANT_JACOBI_SWEEPS Jacobi sweeps (each also writes (b − Ax)² of the x it read, for the
// residual); then an edge-atlas pass u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e. The system's and a sweep's
// channels are named by src/flow/flowLayouts.ts (TFC_SURFACTANT_SYSTEM_*, TFC_JACOBI_SWEEP_*).
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

/** The right side b, the diagonal and the starting guess Γ. */
vec4 tfcSurfactantSystem() {
  int c = tfcCellAt(ivec2(gl_FragCoord.xy));
  float area = tfcCellGeometry(c).w;
  float gammaC = texelFetch(uFilm, tfcCellTexel(c), 0).g;
  vec4 edges = tfcCellEdges(c);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = texelFetch(uSurfactantWeights, tfcCellTexel(c), 0);
  float b = area * gammaC;
  float d = area;
  for (int s = 0; s < 4; s++) {
    int e = tfcEdgeOf(edges[s]);
    b -= uDt * tfcEdgeCells(e).z * sign(edges[s]) * texelFetch(uPrediction, tfcEdgeTexel(e), 0).r * tfcMeanGamma(gammaC, tfcIndex(neighbors[s]));
    d += weight[s];
  }
  vec4 system = vec4(0.0);
  system[TFC_SURFACTANT_SYSTEM_RHS_CHANNEL] = b;
  system[TFC_SURFACTANT_SYSTEM_DIAGONAL_CHANNEL] = d;
  system[TFC_SURFACTANT_SYSTEM_GAMMA_CHANNEL] = gammaC;
  return system;
}

uniform sampler2D uSurfactantRhs;
uniform sampler2D uGuess;
/** The one-hot mask of the channel of uGuess that holds x (the system's Γ, or a sweep's x). */
uniform vec4 uGuessChannel;

/** One Jacobi sweep: the next x and (b − Ax)² of the x read. */
vec4 tfcJacobiSweep() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int c = tfcCellAt(texel);
  vec4 neighbors = tfcCellNeighbors(c);
  vec4 weight = texelFetch(uSurfactantWeights, texel, 0);
  vec4 system = texelFetch(uSurfactantRhs, texel, 0);
  float diagonal = system[TFC_SURFACTANT_SYSTEM_DIAGONAL_CHANNEL];
  float sum = system[TFC_SURFACTANT_SYSTEM_RHS_CHANNEL];
  for (int s = 0; s < 4; s++) sum += weight[s] * dot(texelFetch(uGuess, tfcCellTexel(tfcIndex(neighbors[s])), 0), uGuessChannel);
  float x = dot(texelFetch(uGuess, texel, 0), uGuessChannel);
  float r = sum - diagonal * x;
  vec4 sweep = vec4(0.0);
  sweep[TFC_JACOBI_SWEEP_X_CHANNEL] = sum / diagonal;
  sweep[TFC_JACOBI_SWEEP_RESIDUAL_SQUARED_CHANNEL] = r * r;
  return sweep;
}

uniform sampler2D uSolvedGamma;

/** u_e = u*_e − c_e (Γ'_B − Γ'_A)/d_e (an edge-atlas pass). */
vec4 tfcCorrectEdgeVelocity() {
  int e = tfcEdgeAt(ivec2(gl_FragCoord.xy));
  vec4 cells = tfcEdgeCells(e);
  vec2 prediction = texelFetch(uPrediction, tfcEdgeTexel(e), 0).rg;
  vec4 solvedA = texelFetch(uSolvedGamma, tfcCellTexel(tfcIndex(cells.x)), 0);
  vec4 solvedB = texelFetch(uSolvedGamma, tfcCellTexel(tfcIndex(cells.y)), 0);
  float slope = (solvedB[TFC_JACOBI_SWEEP_X_CHANNEL] - solvedA[TFC_JACOBI_SWEEP_X_CHANNEL]) / cells.w;
  return vec4(prediction.r - prediction.g * slope, 0.0, 0.0, 0.0);
}

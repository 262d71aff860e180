// The reflectance of a stack of films (src/physics/transferMatrix.ts): media 0 (the light's side),
// 1..N the layers, N+1 the far side. Airy/Rouard recursion from the far side in (Born & Wolf §1.6;
// Byrnes 2016, arXiv:1603.02720):
//   Γ_N = r_{N,N+1},
//   Γ_j = r_{j,j+1} + t_{j,j+1} t_{j+1,j} Γ_{j+1} e^{iφ_{j+1}} / (1 − r_{j+1,j} Γ_{j+1} e^{iφ_{j+1}}),
//   φ_j = 4π ñ_j d_j cos θ_j / λ,   R = |Γ_0|² per channel, averaged over the channels.
// Each interface's r and t come from fresnel.glsl's formulas per channel (s, p or the paper's average of
// eqs 4, 8: filmReflectance.glsl's tfcChannelOf), cos θ_j from snell.glsl; one layer is eq (13).
// The stack (src/film/filmStack.ts) is uFilmLayers: a row per layer from the outside in, then the
// inside, a column per spectral bin, each texel a record of FILM_LAYER read by its names; the layer
// count is uFilmLayerCount ≤ TFC_FILM_LAYERS_MAX. Light from inside (the far wall) meets the layers
// in the reverse order, the inside its medium 0 and the outside (uNOutside, real) its far side.
// Domain: the layers of LAYERS_DOMAIN; the light's medium transparent.
#ifndef THIN_FILM_TRANSFER_MATRIX
#define THIN_FILM_TRANSFER_MATRIX
#include "binnedIntegration.glsl"
#include "texelRecord.glsl"

uniform sampler2D uFilmLayers;
uniform int uFilmLayerCount;

// Medium m of the stack as the light meets it, at bin `bin`: its ñ and its thickness (a
// FOLLOWS_FIELD layer takes the field's); the outside is vec2(nOutside, 0).
void tfcStackMedium(int m, int bin, bool fromInside, float nOutside, float fieldThicknessNm, out vec2 n, out float thicknessNm) {
  int count = uFilmLayerCount;
  thicknessNm = 0.0;
  if (fromInside ? m == count + 1 : m == 0) {
    n = vec2(nOutside, 0.0);
    return;
  }
  int row = fromInside ? (m == 0 ? count : count - m) : m - 1;
  vec4 t[TFC_FILM_LAYER_TEXELS];
  for (int i = 0; i < TFC_FILM_LAYER_TEXELS; i++) t[i] = texelFetch(uFilmLayers, ivec2(TFC_FILM_LAYER_TEXELS * bin + i, row), 0);
  n = TFC_RECORD_VEC2(t, TFC_FILM_LAYER_N);
  thicknessNm = TFC_RECORD_FLOAT(t, TFC_FILM_LAYER_FOLLOWS_FIELD) == 1.0 ? fieldThicknessNm : TFC_RECORD_FLOAT(t, TFC_FILM_LAYER_THICKNESS_NM);
}

// Both ways of the interface 1|2 (fresnel.glsl's eqs 5, 6, 9, 10, as tfcFresnelCoefficients gives
// each): the reverse shares the forward's products and denominators, its r the forward's negated
// and its t the far side's 2 n cos θ over the same sum, so one interface costs two divisions, not eight.
void tfcInterfaceBothWays(vec2 n1, vec2 cos1, vec2 n2, vec2 cos2, out InterfaceCoefficients forward, out InterfaceCoefficients backward) {
  if (n1 == n2) {
    forward = InterfaceCoefficients(vec2(0.0), vec2(0.0), vec2(1.0, 0.0), vec2(1.0, 0.0));
    backward = forward;
    return;
  }
  vec2 n1c1 = tfcCMul(n1, cos1);
  vec2 n2c2 = tfcCMul(n2, cos2);
  vec2 n2c1 = tfcCMul(n2, cos1);
  vec2 n1c2 = tfcCMul(n1, cos2);
  vec2 sInverse = tfcCDiv(vec2(1.0, 0.0), n1c1 + n2c2);
  vec2 pInverse = tfcCDiv(vec2(1.0, 0.0), n2c1 + n1c2);
  vec2 rs = tfcCMul(n1c1 - n2c2, sInverse);
  vec2 rp = tfcCMul(n2c1 - n1c2, pInverse);
  forward = InterfaceCoefficients(rs, rp, tfcCMul(2.0 * n1c1, sInverse), tfcCMul(2.0 * n1c1, pInverse));
  backward = InterfaceCoefficients(-rs, -rp, tfcCMul(2.0 * n2c2, sInverse), tfcCMul(2.0 * n2c2, pInverse));
}

// One step of the recursion for one channel (airyStep in the TypeScript): Γ_j from Γ_{j+1}, the
// (r, t) of j→j+1 (`forward`) and j+1→j (`backward`), and z = e^{iφ_{j+1}}; r_{j,j+1} where no
// light crosses (the numerator exactly 0), rather than 0/0.
vec2 tfcRouardStep(vec4 forward, vec4 backward, vec2 gammaInner, vec2 z) {
  vec2 echo = tfcCMul(gammaInner, z);
  vec2 multiple = tfcCMul(tfcCMul(forward.zw, backward.zw), echo);
  return multiple == vec2(0.0) ? forward.xy : forward.xy + tfcCDiv(multiple, vec2(1.0, 0.0) - tfcCMul(backward.xy, echo));
}

// R of the stack at bin `bin`, whose centre is lambdaNm, averaged over the channels.
float tfcLayersReflectance(int bin, float lambdaNm, float nOutside, bool fromInside, float fieldThicknessNm, float cosIncidence) {
  int count = uFilmLayerCount;
  vec2 nLight, nIn, nOut;
  float dIn, dOut;
  tfcStackMedium(0, bin, fromInside, nOutside, fieldThicknessNm, nLight, dIn);
  float na = nLight.x;
  tfcStackMedium(count + 1, bin, fromInside, nOutside, fieldThicknessNm, nIn, dIn);
  tfcStackMedium(count, bin, fromInside, nOutside, fieldThicknessNm, nOut, dOut);
  vec2 cosIn = tfcRefractedCos(nIn, na, cosIncidence);
  vec2 cosOut = tfcRefractedCos(nOut, na, cosIncidence);
  InterfaceCoefficients last = tfcFresnelCoefficients(nOut, cosOut, nIn, cosIn);
  vec2 gamma[TFC_FILM_CHANNELS];
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) gamma[c] = tfcChannelOf(last, tfcChannelKind(c)).xy;
  for (int k = 1; k <= TFC_FILM_LAYERS_MAX; k++) {
    int j = count - k;
    if (j < 0) break;
    nIn = nOut;
    cosIn = cosOut;
    dIn = dOut;
    tfcStackMedium(j, bin, fromInside, nOutside, fieldThicknessNm, nOut, dOut);
    cosOut = tfcRefractedCos(nOut, na, cosIncidence);
    vec2 z = tfcCExpI(tfcCMul(nIn, cosIn) * (12.566370614359172 * dIn / lambdaNm));
    InterfaceCoefficients forward, backward;
    tfcInterfaceBothWays(nOut, cosOut, nIn, cosIn, forward, backward);
    for (int c = 0; c < TFC_FILM_CHANNELS; c++) {
      int kind = tfcChannelKind(c);
      gamma[c] = tfcRouardStep(tfcChannelOf(forward, kind), tfcChannelOf(backward, kind), gamma[c], z);
    }
  }
  float sum = 0.0;
  for (int c = 0; c < TFC_FILM_CHANNELS; c++) sum += tfcCAbs2(gamma[c]);
  return min(1.0, sum / float(TFC_FILM_CHANNELS));
}

// The stack's XYZ, eqs (15)–(18) over binnedIntegration.glsl's bins, each bin's R at its centre:
// a stack has no closed-form mean over a bin (docs/gpu.md#stacks-of-films says why one sample
// per bin of the finer count holds the parity bound). A line source's lines: R at each line's λ,
// the layers' ñ those of the bin it falls in (the stack's texture holds ñ per bin).
TFC_FILM_COLOR tfcLayersBinnedXyz(float nOutside, bool fromInside, float fieldThicknessNm, float cosIncidence) {
  const float width = float(TFC_LAMBDA_MAX_NM - TFC_LAMBDA_MIN_NM) / float(TFC_SPECTRAL_BINS);
  TFC_FILM_COLOR xyz = TFC_FILM_COLOR(0.0);
  for (int i = 0; i < TFC_LIGHT_LINES_MAX && i < uLightLineCount; i++) {
    float l = uLightLines[i].w;
    int bin = clamp(int((l - float(TFC_LAMBDA_MIN_NM)) / width), 0, TFC_SPECTRAL_BINS - 1);
    xyz += tfcLayersReflectance(bin, l, nOutside, fromInside, fieldThicknessNm, cosIncidence) * tfcLineWeight(i);
  }
  if (uLightLineCount > 0) return xyz;
  for (int b = TFC_SPECTRAL_BIN_FIRST; b < TFC_SPECTRAL_BIN_END; b++) {
    float center = float(TFC_LAMBDA_MIN_NM) + (float(b) + 0.5) * width;
    xyz += tfcLayersReflectance(b, center, nOutside, fromInside, fieldThicknessNm, cosIncidence) * tfcBinWeight(b);
  }
  return xyz;
}

#endif

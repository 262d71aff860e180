// Fresnel amplitude coefficients, medium 1 -> medium 2, the paper's sign convention:
//   r^s eq (5), r^p eq (6), t^s eq (9), t^p eq (10). Equal indices are no interface.
// Indices are complex, vec2(n, k) for ñ = n + ik (k = 0: a transparent medium); the formulas hold
// unchanged. Mirrors src/physics/fresnel.ts.
#ifndef THIN_FILM_FRESNEL
#define THIN_FILM_FRESNEL
#include "complex.glsl"

struct InterfaceCoefficients { vec2 rs; vec2 rp; vec2 ts; vec2 tp; };

InterfaceCoefficients tfcFresnelCoefficients(vec2 n1, vec2 cos1, vec2 n2, vec2 cos2) {
  if (n1 == n2) return InterfaceCoefficients(vec2(0.0), vec2(0.0), vec2(1.0, 0.0), vec2(1.0, 0.0));
  vec2 n1c1 = tfcCMul(n1, cos1);
  vec2 n2c2 = tfcCMul(n2, cos2);
  vec2 n2c1 = tfcCMul(n2, cos1);
  vec2 n1c2 = tfcCMul(n1, cos2);
  vec2 sDen = n1c1 + n2c2;
  vec2 pDen = n2c1 + n1c2;
  return InterfaceCoefficients(
    tfcCDiv(n1c1 - n2c2, sDen),
    tfcCDiv(n2c1 - n1c2, pDen),
    tfcCDiv(2.0 * n1c1, sDen),
    tfcCDiv(2.0 * n1c1, pDen));
}

#endif

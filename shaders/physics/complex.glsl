// Complex arithmetic, complex numbers as vec2(re, im); sums, differences and real scaling are
// plain vec2 operations. Mirrors src/physics/complex.ts.
#ifndef THIN_FILM_COMPLEX
#define THIN_FILM_COMPLEX

vec2 tfcCMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

// a / b by Smith's algorithm (no overflow in |b|^2); b != 0.
vec2 tfcCDiv(vec2 a, vec2 b) {
  if (abs(b.x) >= abs(b.y)) {
    float t = b.y / b.x;
    float d = b.x + b.y * t;
    return vec2(a.x + a.y * t, a.y - a.x * t) / d;
  }
  float t = b.x / b.y;
  float d = b.x * t + b.y;
  return vec2(a.x * t + a.y, a.y * t - a.x) / d;
}

float tfcCAbs2(vec2 a) { return dot(a, a); }

// e^{i z} = e^{-Im z} (cos Re z + i sin Re z)
vec2 tfcCExpI(vec2 z) { return exp(-z.y) * vec2(cos(z.x), sin(z.x)); }

// The principal square root (Re >= 0), formed without cancellation.
vec2 tfcCSqrt(vec2 z) {
  if (z == vec2(0.0)) return vec2(0.0);
  float m = sqrt(0.5 * (abs(z.x) + length(z)));
  return z.x >= 0.0 ? vec2(m, z.y / (2.0 * m)) : vec2(abs(z.y) / (2.0 * m), z.y >= 0.0 ? m : -m);
}

#endif

// XYZ -> linear RGB with a matrix from src/physics/colorConversions.ts (eq 19, eq 20 or Display
// P3), and the display-gamut test behind the wide-gamut hatching. The sRGB transfer function is
// applied once, by three.js's <colorspace_fragment>. Mirrors src/physics/colorConversions.ts.
#ifndef THIN_FILM_COLOR_CONVERSIONS
#define THIN_FILM_COLOR_CONVERSIONS

vec3 tfcApplyMatrix3(mat3 m, vec3 v) { return m * v; }

// No TypeScript twin: only the shader hatches out-of-gamut pixels (the CPU image and the plots clip).
bool tfcOutsideGamut(vec3 linearRgb) { return any(lessThan(linearRgb, vec3(-1e-4))) || any(greaterThan(linearRgb, vec3(1.0 + 1e-4))); }

#endif

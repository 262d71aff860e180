// The film's colour as the shaders carry it (mirrors src/physics/environmentMatrix.ts): its XYZ under
// the light (a vec3), or with TFC_ENVIRONMENT_MATRIX its environment matrix M (a mat3): column j the
// film's XYZ under the light times basis spectrum j, so that M c is its reflection of light of
// colour c (linear sRGB relative to the light's white), an integral of two spectra, and M (1, 1, 1)
// its XYZ under the light itself. The sums over bins, lines and series orders are written once for
// both: a float times either, and either plus its own kind.
#ifndef THIN_FILM_ENVIRONMENT_MATRIX
#define THIN_FILM_ENVIRONMENT_MATRIX

#ifdef TFC_ENVIRONMENT_MATRIX
#define TFC_FILM_COLOR mat3
// XYZ of the film's reflection of light of colour c: M c.
vec3 tfcReflectedXyz(mat3 m, vec3 c) { return m * c; }
#else
#define TFC_FILM_COLOR vec3
#endif

#endif

// A film at rest after draining: the height alone sets it. Mirrors src/fields/drainageField.ts.
#include "drainedFilm.glsl"

float tfcThicknessAt(vec3 p) { return tfcDrainedThicknessNm(p.y, p.y); }

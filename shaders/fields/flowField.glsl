// The flowing film: the full thickness h̄·η sampled from the simulation's padded film (src/gpuFilmDynamics/,
// uFlowFilm), bilinear within a cube face and seamless across them, within the table's range. The
// view's y-up point p is the simulation's z-up direction (p.x, −p.z, p.y). Mirrors src/fields/flowField.ts.
#include "cubeSphereSampler.glsl"
#include "flowFilm.glsl"
uniform float uThicknessNm;
uniform float uFlowMaxThicknessNm;
uniform sampler2D uFlowFilm;

float tfcThicknessAt(vec3 p) {
  TfcFilm film = tfcFilm(tfcSamplePadded(uFlowFilm, vec3(p.x, -p.z, p.y)));
  return clamp(uThicknessNm * film.eta, 0.0, uFlowMaxThicknessNm);
}

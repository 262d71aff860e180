// The halo pass (the twin's padField; src/gpuFilmDynamics/flowUniforms.ts makes these uniforms): tfcPadField
// of cubeSphereSampler.glsl fills a padded atlas from the field uField through the halo's tap table
// uHaloTaps. The function takes the two as arguments, since the bubble's shader samples a padded
// film with the same file and has no taps; this pass declares them here.
#include "cubeSphereSampler.glsl"
uniform sampler2D uHaloTaps;
uniform sampler2D uField;

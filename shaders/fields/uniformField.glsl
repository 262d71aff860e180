// The same thickness everywhere. Mirrors src/fields/uniformField.ts.
uniform float uThicknessNm;

float tfcThicknessAt(vec3 p) { return uThicknessNm; }

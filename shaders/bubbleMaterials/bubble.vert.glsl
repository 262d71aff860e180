// The bubble's vertex stage: a unit sphere; world position and normal for θ_i, the object-space
// point for the thickness field.
varying vec3 vWorldPosition;
varying vec3 vWorldNormal;
varying vec3 vSpherePoint;

void main() {
  vSpherePoint = normalize(position);
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorldPosition = world.xyz;
  vWorldNormal = normalize(mat3(modelMatrix) * normal);
  gl_Position = projectionMatrix * viewMatrix * world;
}

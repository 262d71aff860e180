import { BackSide, type DataTexture, ShaderMaterial, Vector2 } from 'three';
import { ENVIRONMENT_KINDS, STAND_IN_ENVIRONMENT, environmentKind, isHdrEnvironment } from '../environments/environments.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { enumDefines } from '../gpu/enumDefines.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';

/** What shaders/bubbleMaterials/environment.glsl needs: which environment, its rotation, and the exposure on all light. */
export type EnvironmentSettings = Pick<FilmSettings, 'env' | 'envRotationDeg' | 'exposure'>;

/**
 * TFC_ENVIRONMENT for the environment shown: its kind (the caller shows the stand-in until an HDR
 * map has arrived).
 */
export const environmentDefines = (s: Pick<FilmSettings, 'env'>): Record<string, number> =>
  enumDefines('TFC_ENVIRONMENT', ENVIRONMENT_KINDS, environmentKind(s.env));

/** The uniforms shaders/bubbleMaterials/environment.glsl reads, plus the exposure. */
export const environmentUniforms = () => ({
  uEnvironmentMap: { value: null as DataTexture | null },
  /** The map's turn about +y as (cos, sin), computed here once rather than per fragment. */
  uEnvironmentTurn: { value: new Vector2(1, 0) },
  uExposure: { value: 1 },
});

/** Points a material at the environment shown (`map`: its texture, for an HDR `env`). */
export function updateEnvironmentUniforms(m: ShaderMaterial, s: EnvironmentSettings, map: DataTexture | null): void {
  if (isHdrEnvironment(s.env) !== (map !== null)) throw new Error(`environment ${s.env} shown with${map ? '' : 'out'} a map`);
  const u = m.uniforms;
  u.uEnvironmentMap!.value = map;
  const turn = (s.envRotationDeg * Math.PI) / 180;
  (u.uEnvironmentTurn!.value as Vector2).set(Math.cos(turn), Math.sin(turn));
  u.uExposure!.value = s.exposure;
}

/** The background: a large sphere seen from inside, showing the environment in each view ray's direction × the exposure, tone mapped like the bubble. */
export function createBackgroundMaterial(): ShaderMaterial {
  return new ShaderMaterial({
    side: BackSide,
    defines: environmentDefines({ env: STAND_IN_ENVIRONMENT }),
    uniforms: environmentUniforms(),
    // The direction from the camera, not from the sphere's centre: the environment is at infinity, as the bubble sees it.
    vertexShader: `varying vec3 vDirection;
void main() {
  vDirection = (modelMatrix * vec4(position, 1.0)).xyz - cameraPosition;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`,
    fragmentShader: `${shaderSource('environment.glsl')}
varying vec3 vDirection;
void main() {
  gl_FragColor = vec4(uExposure * tfcEnvironmentRadiance(vDirection), 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}`,
  });
}

/** Shows an environment on the background material. */
export function updateBackgroundMaterial(m: ShaderMaterial, s: EnvironmentSettings, map: DataTexture | null): void {
  setDefines(m, environmentDefines(s));
  updateEnvironmentUniforms(m, s, map);
}

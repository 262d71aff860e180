import { BackSide, type DataTexture, ShaderMaterial, Vector2, Vector3 } from 'three';
import {
  ENVIRONMENT_KINDS,
  STAND_IN_ENVIRONMENT,
  environmentColor,
  environmentKind,
  environmentText,
  isHdrEnvironment,
} from '../environments/environments.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { enumDefines } from '../gpu/enumDefines.ts';
import { setDefines } from '../gpu/materialDefines.ts';
import { shaderSource } from '../gpu/shaderSource.ts';

/** What shaders/bubbleMaterials/environment.glsl needs: which environment, its rotation, and the exposure on all light. */
export type EnvironmentSettings = Pick<FilmSettings, 'env' | 'envRotationDeg' | 'exposure'>;

/**
 * TFC_ENVIRONMENT for the environment shown: its kind (the caller shows the stand-in until an HDR
 * map has arrived), never its colour, which is a uniform: a change of colour keeps the program.
 */
export const environmentDefines = (s: Pick<FilmSettings, 'env'>): Record<string, number> =>
  enumDefines('TFC_ENVIRONMENT', ENVIRONMENT_KINDS, environmentKind(s.env));

/** The uniforms shaders/bubbleMaterials/environment.glsl reads, plus the exposure. */
export const environmentUniforms = () => ({
  uEnvironmentMap: { value: null as DataTexture | null },
  /** The map's turn about +y as (cos, sin), computed here once rather than per fragment. */
  uEnvironmentTurn: { value: new Vector2(1, 0) },
  /** A uniform environment's colour (linear sRGB relative to the light's white); black for the others. */
  uEnvironmentColor: { value: new Vector3() },
  uExposure: { value: 1 },
});

/** Points a material at the environment shown (`map`: its texture, for an HDR `env`; a uniform one's colour). */
export function updateEnvironmentUniforms(m: ShaderMaterial, s: EnvironmentSettings, map: DataTexture | null): void {
  if (isHdrEnvironment(s.env) !== (map !== null))
    throw new Error(`environment ${environmentText(s.env)} shown with${map ? '' : 'out'} a map`);
  const u = m.uniforms;
  u.uEnvironmentMap!.value = map;
  (u.uEnvironmentColor!.value as Vector3).set(...(environmentColor(s.env) ?? [0, 0, 0]));
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

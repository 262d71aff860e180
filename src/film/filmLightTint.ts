import { type ShaderMaterial, Vector3 } from 'three';
import type { LightTint } from '../physics/lightTint.ts';

/**
 * The uniform of shaders/film/filmLightTint.glsl: the light's tint, a colour the film's environment
 * matrix maps (its planes are the untinted light's: physics/spectralWeights.ts, planesLight), read
 * only by a program that computes that matrix.
 */
export const lightTintUniforms = () => ({ uLightTint: { value: new Vector3(1, 1, 1) } });

/** Sets lightTintUniforms to `tint`. */
export const setLightTintUniform = (u: ShaderMaterial['uniforms'], tint: LightTint): void =>
  void (u.uLightTint!.value as Vector3).set(...tint);

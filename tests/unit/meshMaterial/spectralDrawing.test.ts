/**
 * The film's drawing loaded apart (src/meshMaterial/spectralDrawing.ts), as a user of the entry
 * meets it: a material made spectral before the drawing arrives keeps three's film in a program of
 * its own key, and whenSpectralReady is kept once the film can be drawn. This file is the first
 * of its module state to make a material spectral (vitest isolates each file's modules).
 */
import { MeshPhysicalMaterial, ShaderLib } from 'three';
import { describe, expect, it } from 'vitest';
import { spectralIridescence, whenSpectralReady } from '../../../src/meshMaterial/spectralIridescence.ts';
import { ParameterError } from '../../../src/input/validate.ts';

const shaderObject = () => ({ fragmentShader: ShaderLib.physical.fragmentShader, vertexShader: '', uniforms: {}, defines: {} });
const isSpectral = (fragment: string) => fragment.includes('tfcSpectralIridescence( material.iridescenceThickness');
const compiled = (m: MeshPhysicalMaterial) => {
  const shader = shaderObject();
  m.onBeforeCompile(shader as never, null as never);
  return shader.fragmentShader;
};

describe('whenSpectralReady', () => {
  it("is kept once the film's drawing is loaded: until then three's film, in a program keyed apart; then a new version, the film", async () => {
    const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    const loadingKey = m.customProgramCacheKey();
    expect(isSpectral(compiled(m))).toBe(false);
    const version = m.version;
    await whenSpectralReady(m);
    expect(m.version).toBeGreaterThan(version);
    expect(m.customProgramCacheKey()).not.toBe(loadingKey);
    expect(isSpectral(compiled(m))).toBe(true);
    // Made spectral once the drawing is here: ready at once, the film in its first program.
    const later = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    expect(isSpectral(compiled(later))).toBe(true);
    await expect(whenSpectralReady(later)).resolves.toBeUndefined();
  });

  it('refuses a material that is not spectral, naming it', async () => {
    await expect(whenSpectralReady(new MeshPhysicalMaterial())).rejects.toThrow(ParameterError);
    await expect(whenSpectralReady(new MeshPhysicalMaterial())).rejects.toThrow(/whenSpectralReady: the material is not spectral/);
  });
});

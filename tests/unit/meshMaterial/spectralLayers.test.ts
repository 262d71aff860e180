/**
 * A stack of films in the spectral material (`layers`): taken as a text or a list and checked as
 * the demo's `layers` is, carried by clone and JSON; `exact` runs the stack's recursion over the
 * base, a method with none for a stack (`fourier`) gives way to the table.
 */
import { MaterialLoader, Scene, ShaderLib } from 'three';
import { beforeAll, describe, expect, it, vi } from 'vitest';
import { loadDrawing } from '../../../src/meshMaterial/spectralDrawing.ts';
import { ThinFilmMaterial } from '../../../src/meshMaterial/thinFilmMaterial.ts';
import { parameterOf } from './parameterOf.ts';
import { enumCode } from '../../../src/gpu/enumDefines.ts';
import { FILM_METHODS } from '../../../src/methods/methods.ts';

// The film's drawing is loaded apart (spectralDrawing.ts): these tests compile and draw with it.
beforeAll(() => loadDrawing());

const shaderObject = () => ({ fragmentShader: ShaderLib.physical.fragmentShader, vertexShader: '', uniforms: {}, defines: {} });
const BRAGG = '(2.35:56.6/1.46:91.1)*8';
const NACRE = [
  { n: 1.68, thicknessNm: 'd' },
  { n: 1.43, thicknessNm: 30 },
] as const;

describe('a stack of films in the spectral material', () => {
  it('takes its layers as a text or a list, checked as the demo takes them, and none by default', () => {
    const m = new ThinFilmMaterial({ mode: 'exact', base: 1.52 });
    expect(m.layers).toEqual([]);
    m.layers = BRAGG;
    expect(m.layers).toHaveLength(16);
    expect(m.layers[1]).toEqual({ n: 1.46, thicknessNm: 91.1 });
    m.layers = NACRE;
    expect(m.layers).toEqual(NACRE);
    for (const bad of ['1.5:-3', 'Unobtainium:100', '(1.5:100)*65', [{ n: 1.5 }], 42])
      expect(
        parameterOf(() => (m.layers = bad as never)),
        JSON.stringify(bad),
      ).toBe('layers');
    expect(m.layers).toEqual(NACRE);
  });

  it("runs the recursion in `exact`, its uniforms the stack's, the d layers at three's thickness", () => {
    const m = new ThinFilmMaterial({
      mode: 'exact',
      base: 1.53,
      layers: NACRE,
      iridescenceThicknessMinimum: 100,
      iridescenceThicknessMaximum: 400,
    });
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(shader.defines).toMatchObject({ TFC_FILM_LAYERS: 1 });
    m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);
    const u = shader.uniforms as Record<string, { value: unknown }>;
    expect(u.uFilmLayerCount!.value).toBe(2);
    expect(u.uFilmLayers!.value).not.toBeNull();
    m.dispose();
  });

  it('draws the table in place of `fourier` for a stack, and `fourier` again for the one film', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const m = new ThinFilmMaterial({ mode: 'fourier', layers: BRAGG });
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(shader.defines).toHaveProperty('TFC_FILM_MODE', enumCode('TFC_FILM_MODE', FILM_METHODS, 'table'));
    expect(m.mode).toBe('fourier');
    m.layers = [];
    const single = shaderObject();
    m.onBeforeCompile(single as never, null as never);
    expect(single.defines).toHaveProperty('TFC_FILM_MODE', enumCode('TFC_FILM_MODE', FILM_METHODS, 'fourier'));
    warn.mockRestore();
  });

  it('carries its layers through clone and JSON', () => {
    const m = new ThinFilmMaterial({ mode: 'exact', layers: NACRE });
    expect(m.clone().layers).toEqual(NACRE);
    MaterialLoader.registerMaterial(ThinFilmMaterial.type, ThinFilmMaterial);
    const loaded = new MaterialLoader().parse(JSON.parse(JSON.stringify(m.toJSON())) as never) as ThinFilmMaterial;
    expect(loaded.layers).toEqual(NACRE);
  });
});

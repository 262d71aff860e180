/**
 * The spectral material as a three.js user meets it, in Node (three's materials need no GPU to be
 * made, cloned, serialised and loaded, or to have onBeforeCompile run on a shader object): a
 * material chained through two other onBeforeCompile users, cloned, serialised and loaded back,
 * an option change that disposes nothing in use, and bad values met inside render warned about
 * and clamped, never thrown. The table, drawn on the GPU, is followed in tests/e2e/material.spec.ts.
 */
import {
  BoxGeometry,
  type Material,
  MaterialLoader,
  Mesh,
  MeshPhysicalMaterial,
  ObjectLoader,
  ShaderChunk,
  Scene,
  ShaderLib,
  type Texture,
} from 'three';
import { afterEach, beforeAll, describe, expect, it, vi } from 'vitest';
import { loadDrawing } from '../../../src/meshMaterial/spectralDrawing.ts';
import { spectralIridescence } from '../../../src/meshMaterial/spectralIridescence.ts';
import { isSpectralIridescence } from '../../../src/meshMaterial/spectralFilm.ts';
import { OPTION_NAMES, type SpectralIridescenceOptions } from '../../../src/meshMaterial/spectralIridescenceOptions.ts';
import { ThinFilmMaterial } from '../../../src/meshMaterial/thinFilmMaterial.ts';
import { ParameterError } from '../../../src/input/validate.ts';

// The film's drawing is loaded apart (spectralDrawing.ts): these tests compile and draw with it.
beforeAll(() => loadDrawing());

/** What three hands onBeforeCompile: the physical material's shaders, uniforms and defines. */
const shaderObject = () => ({
  fragmentShader: ShaderLib.physical.fragmentShader,
  vertexShader: '',
  uniforms: {} as Record<string, { value: unknown }>,
  defines: {} as Record<string, unknown>,
});
/** onBeforeCompile as three calls it when it compiles `m`'s program; the shader it leaves. */
const compile = (m: Material) => {
  const shader = shaderObject();
  m.onBeforeCompile(shader as never, null as never);
  return shader;
};
/** onBeforeRender as three calls it before drawing `m` (null renderer: no table is drawn outside table mode). */
const draw = (m: Material) => m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);
/** The film's own GLSL function, written in once per shader. */
const FILM_FUNCTION = 'vec3 tfcSpectralIridescence(';
/** Whether a compiled fragment shader holds the spectral film in place of three's. */
const isSpectral = (fragment: string) => fragment.includes('tfcSpectralIridescence( material.iridescenceThickness');
const occurrences = (text: string, part: string) => text.split(part).length - 1;

const warnings = () => vi.spyOn(console, 'warn').mockImplementation(() => {});
afterEach(() => vi.restoreAllMocks());

describe('a material chained through two other onBeforeCompile users', () => {
  it("runs the first user's (set before the upgrade), the second's (chained after it by three's idiom), then the film, once", () => {
    const ran: string[] = [];
    const m = new MeshPhysicalMaterial({ iridescence: 1 });
    m.onBeforeCompile = (shader) => {
      ran.push(isSpectral(shader.fragmentShader) ? 'first, after the film' : 'first');
      shader.defines = { ...shader.defines, FIRST_USER: 1 };
    };
    spectralIridescence(m, { mode: 'fourier' });
    // three's chaining idiom: the hook read is called on the material.
    // eslint-disable-next-line @typescript-eslint/unbound-method
    const previous = m.onBeforeCompile;
    m.onBeforeCompile = (shader, renderer) => {
      previous.call(m, shader, renderer);
      ran.push(isSpectral(shader.fragmentShader) ? 'second, after the film' : 'second');
      shader.fragmentShader = `// second user\n${shader.fragmentShader}`;
    };
    const shader = compile(m);
    expect(ran).toEqual(['first', 'second']);
    expect(shader.fragmentShader.startsWith('// second user\n')).toBe(true);
    expect(isSpectral(shader.fragmentShader)).toBe(true);
    expect(occurrences(shader.fragmentShader, FILM_FUNCTION)).toBe(1);
    // The film's defines are those of the same film with no user: the users' edits kept beside them.
    const alone = compile(spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }), { mode: 'fourier' }));
    expect(shader.defines).toEqual({ ...alone.defines, FIRST_USER: 1 });
  });

  it("chains the program key the same way: the film's part once, the users' edits in it", () => {
    const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    const plain = m.customProgramCacheKey();
    // eslint-disable-next-line @typescript-eslint/unbound-method -- three's chaining idiom, as above
    const previous = m.customProgramCacheKey;
    m.customProgramCacheKey = () => `${previous.call(m)} second-user`;
    const key = m.customProgramCacheKey();
    expect(key).toBe(`${plain} second-user`);
    expect(occurrences(key, 'spectral-iridescence')).toBe(1);
  });
});

/** Every option away from its default: a metal from its colour (no base), or a named base. */
const OPTIONS: SpectralIridescenceOptions = {
  mode: 'fourier',
  illuminant: { daylightCct: 7500 },
  polarization: 's',
  normalization: 'white',
  film: 'TiO2',
  edgeTint: [1, 0.5, 0.25],
  quality: { exactSpectralBins: 45, table: { rows: 64 } },
};
const MADE: readonly (readonly [string, () => MeshPhysicalMaterial])[] = [
  [
    'an upgraded MeshPhysicalMaterial on a metal of its colour',
    () => spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1, metalness: 1, color: 0xffc356 }), OPTIONS),
  ],
  [
    'a ThinFilmMaterial on titanium',
    () => new ThinFilmMaterial({ ...OPTIONS, base: 'Ti', edgeTint: null, iridescenceThicknessMaximum: 650 }),
  ],
];

MaterialLoader.registerMaterial(ThinFilmMaterial.type, ThinFilmMaterial);
/** The material written by toJSON, as text, and read back by three's MaterialLoader. */
const loaded = (m: Material) => new MaterialLoader().parse(JSON.parse(JSON.stringify(m.toJSON())) as never);

describe('cloned, serialised and loaded back', () => {
  it.each(MADE)('%s keeps its film: the same options, physical parameters, defines and program key', (_, make) => {
    const m = make();
    if (!isSpectralIridescence(m)) throw new Error('not spectral');
    for (const copy of [m.clone(), loaded(m)]) {
      if (!isSpectralIridescence(copy)) throw new Error('the copy is not spectral');
      for (const name of OPTION_NAMES) expect(copy[name], name).toEqual(m[name]);
      expect([copy.iridescence, copy.metalness, copy.color.getHex(), copy.iridescenceThicknessMaximum]).toEqual([
        m.iridescence,
        m.metalness,
        m.color.getHex(),
        m.iridescenceThicknessMaximum,
      ]);
      expect(compile(copy).defines).toEqual(compile(m).defines);
      expect(copy.customProgramCacheKey()).toBe(m.customProgramCacheKey());
    }
  });

  it("is a ThinFilmMaterial in JSON, made again by three's MaterialLoader; its instances keep three's physical shader's type", () => {
    const [upgraded, thin] = MADE.map(([, make]) => make());
    for (const m of [upgraded!, thin!]) {
      expect(m.toJSON().type).toBe('ThinFilmMaterial');
      expect(loaded(m)).toBeInstanceOf(ThinFilmMaterial);
    }
    expect(ThinFilmMaterial.type).toBe('ThinFilmMaterial');
    expect([thin!.type, (thin as ThinFilmMaterial).isThinFilmMaterial]).toEqual(['MeshPhysicalMaterial', true]);
    expect(upgraded!.type).toBe('MeshPhysicalMaterial');
  });

  it("comes back in a scene saved by toJSON and loaded by three's ObjectLoader", () => {
    const m = MADE[0]![1]();
    const mesh = new Mesh(new BoxGeometry(), m);
    const back = (new ObjectLoader().parse(JSON.parse(JSON.stringify(mesh.toJSON()))) as Mesh).material as MeshPhysicalMaterial;
    expect(back).toBeInstanceOf(ThinFilmMaterial);
    expect(compile(back).defines).toEqual(compile(m).defines);
    if (!isSpectralIridescence(back) || !isSpectralIridescence(m)) throw new Error('not spectral');
    for (const name of OPTION_NAMES) expect(back[name], name).toEqual(m[name]);
  });

  it("refuses a JSON's bad film options by name", () => {
    const json = { ...(new ThinFilmMaterial().toJSON() as object) };
    const parameterOf = (spectral: unknown) => {
      try {
        new MaterialLoader().parse({ ...json, spectralIridescence: spectral });
      } catch (e) {
        if (e instanceof ParameterError) return e.parameter;
        throw e;
      }
      return 'accepted';
    };
    expect(parameterOf('table')).toBe('spectralIridescence');
    expect(parameterOf({ mode: 'bogus' })).toBe('mode');
    expect(parameterOf({ mode: 'exact' })).toBe('accepted');
  });
});

describe('an option change', () => {
  it("moves the version for the new program and keeps the light's textures in use: no dispose event", () => {
    const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }), { mode: 'fourier' });
    const uniforms = compile(m).uniforms as Record<string, { value: Texture | null }>;
    draw(m);
    const textures = [uniforms.uSpectralBins!.value!, uniforms.uSpectralTransform!.value!];
    const disposed: string[] = [];
    m.addEventListener('dispose', () => disposed.push('the material'));
    textures.forEach((t, i) => t.addEventListener('dispose', () => disposed.push(`texture ${i}`)));
    const [version, key] = [m.version, m.customProgramCacheKey()];
    m.polarization = 's'; // fourier mode's program reads the polarisation; its light textures do not
    draw(m);
    expect(m.customProgramCacheKey()).not.toBe(key);
    expect(m.version).toBeGreaterThan(version);
    expect(uniforms.uSpectralBins!.value).toBe(textures[0]);
    expect(uniforms.uSpectralTransform!.value).toBe(textures[1]);
    expect(disposed).toEqual([]);
  });
});

describe('inside render, nothing throws', () => {
  it('an out-of-range value set after loading is drawn clamped to its range, with one warning per parameter', () => {
    const m = loaded(
      spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.33 }), { mode: 'fourier' }),
    ) as MeshPhysicalMaterial;
    const uniforms = compile(m).uniforms as Record<string, { value: unknown }>;
    m.iridescenceIOR = 5;
    m.iridescenceThicknessMaximum = -10;
    const warn = warnings();
    expect(() => draw(m)).not.toThrow();
    draw(m);
    const messages = warn.mock.calls.map((c) => String(c[0]));
    expect(messages).toHaveLength(2); // once per parameter, not per frame
    expect(messages[0]).toMatch(/iridescenceIOR 5 .*\[1, 4\]/);
    expect(messages[1]).toMatch(/iridescenceThicknessMaximum -10 .*\[0, 20000\] nm/);
    expect(uniforms.uNFilm!.value).toEqual([4, 0]); // the domain's upper end (ñ = n + 0i)
  });

  it("a three.js release whose lights_fragment_begin lacks the film's line: three's film, one warning naming the line", () => {
    const chunk = ShaderChunk.lights_fragment_begin;
    const call = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor )';
    expect(chunk).toContain(call);
    const warn = warnings();
    try {
      ShaderChunk.lights_fragment_begin = chunk.replace(call, 'evalIridescenceOfAnotherRelease()');
      const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }), { mode: 'fourier' });
      let shader = shaderObject();
      expect(() => (shader = compile(m))).not.toThrow();
      compile(m);
      expect(isSpectral(shader.fragmentShader)).toBe(false);
      expect(shader.fragmentShader).toBe(ShaderLib.physical.fragmentShader);
      expect(warn).toHaveBeenCalledTimes(1);
      expect(String(warn.mock.calls[0]![0])).toContain(call);
    } finally {
      ShaderChunk.lights_fragment_begin = chunk;
    }
  });
});

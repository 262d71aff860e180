/**
 * The spectral material as a three.js user meets it, in Node (three's materials need no GPU to be
 * made, copied, or to have onBeforeCompile run on a shader object): hooks chained, program keys,
 * clone and copy, options as properties, the one-object constructor, and the quality's checks.
 */
import { MeshPhysicalMaterial, Scene, ShaderLib, Texture, type Vector3 } from 'three';
import { beforeAll, describe, expect, it, vi } from 'vitest';
import { loadDrawing } from '../../../src/meshMaterial/spectralDrawing.ts';
import { spectralIridescence, whenSpectralReady } from '../../../src/meshMaterial/spectralIridescence.ts';
import { isSpectralIridescence } from '../../../src/meshMaterial/spectralFilm.ts';
import { ThinFilmMaterial } from '../../../src/meshMaterial/thinFilmMaterial.ts';
import { parameterOf } from './parameterOf.ts';
import { DEFAULT_FILM_QUALITY, filmQualityFrom } from '../../../src/settings/filmQuality.ts';

// The film's drawing is loaded apart (spectralDrawing.ts): these tests compile and draw with it.
beforeAll(() => loadDrawing());

/** What three hands onBeforeCompile: the physical material's shaders, uniforms and defines. */
const shaderObject = () => ({ fragmentShader: ShaderLib.physical.fragmentShader, vertexShader: '', uniforms: {}, defines: {} });
/** Whether a compiled fragment shader holds the spectral film in place of three's. */
const isSpectral = (fragment: string) => fragment.includes('tfcSpectralIridescence( material.iridescenceThickness');

describe("the user's hooks", () => {
  it("calls the user's onBeforeCompile first, set before or after the upgrade, and keys the program by it", () => {
    const seen: string[] = [];
    const before = new MeshPhysicalMaterial({ iridescence: 1 });
    before.onBeforeCompile = (shader) => {
      seen.push(isSpectral(shader.fragmentShader) ? 'spectral already' : 'three');
      shader.fragmentShader = `// user\n${shader.fragmentShader}`;
    };
    spectralIridescence(before);
    const shader = shaderObject();
    before.onBeforeCompile(shader as never, null as never);
    expect(seen).toEqual(['three']);
    expect(shader.fragmentShader.startsWith('// user\n')).toBe(true);
    expect(isSpectral(shader.fragmentShader)).toBe(true);

    const after = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    const plainKey = after.customProgramCacheKey();
    after.onBeforeCompile = (s) => void (s.defines = { ...s.defines, USER_EDIT: 1 });
    const later = shaderObject();
    after.onBeforeCompile(later as never, null as never);
    expect(later.defines).toHaveProperty('USER_EDIT', 1);
    expect(isSpectral(later.fragmentShader)).toBe(true);
    // three's default key is onBeforeCompile's text: a different user edit is a different program.
    expect(after.customProgramCacheKey()).not.toBe(plainKey);
    after.customProgramCacheKey = () => 'user-key-7';
    expect(after.customProgramCacheKey()).toContain('user-key-7');
    expect(after.customProgramCacheKey()).toContain('spectral-iridescence');
  });

  it("keeps three's film, with a warning, where the user's onBeforeCompile took the chunks away", () => {
    const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    m.onBeforeCompile = (s) => void (s.fragmentShader = s.fragmentShader.replace('#include <lights_fragment_begin>', '// gone'));
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(isSpectral(shader.fragmentShader)).toBe(false);
    expect(warn).toHaveBeenCalledTimes(1);
    warn.mockRestore();
  });

  it('says once why another method draws the film: a line source in a table, a stack in `fourier`', async () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const prepared = async (options: Parameters<typeof spectralIridescence>[1]) => {
      const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }), options);
      for (let i = 0; i < 2; i++) await whenSpectralReady(m);
    };
    await prepared({ illuminant: 'Na' });
    await prepared({ mode: 'fourier', layers: '(2.35:56.6/1.46:91.1)*8' });
    await prepared({ illuminant: 'Na', mode: 'exact' });
    expect(warn.mock.calls.map(([text]) => String(text))).toEqual([
      expect.stringMatching(/mode table: a table's grid cannot hold a line source's fringes; drawn with mode exact/),
      expect.stringMatching(/mode fourier: it has no closed form for a stack of films; drawn with mode table/),
    ]);
    warn.mockRestore();
  });

  it("calls the user's onBeforeRender", () => {
    const m = new MeshPhysicalMaterial({ iridescence: 0 });
    const calls: unknown[] = [];
    m.onBeforeRender = (renderer) => void calls.push(renderer);
    spectralIridescence(m);
    m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);
    expect(calls).toEqual([null]);
  });
});

describe('clone and copy', () => {
  it("a patched MeshPhysicalMaterial's clone is spectral with its options; copy carries them", () => {
    const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.5 }), {
      mode: 'fourier',
      illuminant: 'D55',
    });
    const c = m.clone();
    expect(c).not.toBe(m);
    expect(isSpectralIridescence(c)).toBe(true);
    expect(c.iridescenceIOR).toBe(1.5);
    if (!isSpectralIridescence(c)) return;
    expect([c.mode, c.illuminant]).toEqual(['fourier', 'D55']);
    const shader = shaderObject();
    c.onBeforeCompile(shader as never, null as never);
    expect(isSpectral(shader.fragmentShader)).toBe(true);
    // The clone's options are its own.
    c.mode = 'exact';
    expect(m.mode).toBe('fourier');
    const target = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    target.copy(c);
    expect(target.mode).toBe('exact');
  });

  it('a ThinFilmMaterial clones as a ThinFilmMaterial with its options, and copies options from another', () => {
    const m = new ThinFilmMaterial({ iridescenceIOR: 1.33, mode: 'exact', polarization: 's', quality: { exactSpectralBins: 45 } });
    const c = m.clone();
    expect(c).toBeInstanceOf(ThinFilmMaterial);
    expect(c.isThinFilmMaterial).toBe(true);
    expect([c.mode, c.polarization, c.quality.exactSpectralBins, c.iridescenceIOR]).toEqual(['exact', 's', 45, 1.33]);
    expect(new ThinFilmMaterial().copy(m).mode).toBe('exact');
  });
});

describe('options as properties', () => {
  it('reads and sets each option, checked as the constructor checks it', () => {
    const m = new ThinFilmMaterial({ iridescenceIOR: 1.33, mode: 'table', illuminant: 'D65' });
    expect([m.mode, m.illuminant, m.iridescence]).toEqual(['table', 'D65', 1]);
    m.illuminant = { daylightCct: 7500 };
    expect(m.illuminant).toEqual({ daylightCct: 7500 });
    expect(parameterOf(() => (m.mode = 'bogus' as 'table'))).toBe('mode');
    expect(parameterOf(() => (m.illuminant = { daylightCct: 1000 }))).toBe('illuminant');
    expect(m.lightTint).toEqual([1, 1, 1]);
    m.lightTint = [1, 0.5, 0.2];
    expect(m.lightTint).toEqual([1, 0.5, 0.2]);
    for (const bad of [[1, 1.5, 0], [1, 1], [0, -0.1, 0], '1,1,1'])
      expect(parameterOf(() => (m.lightTint = bad as never))).toBe('lightTint');
    expect(m.lightTint).toEqual([1, 0.5, 0.2]);
    expect(parameterOf(() => (m.polarization = 'circular' as 's'))).toBe('polarization');
    expect(parameterOf(() => (m.normalization = 'peak' as 'white'))).toBe('normalization');
    expect(parameterOf(() => (m.quality = { exactSpectralBins: 7 }))).toBe('quality.exactSpectralBins');
    expect(m.mode).toBe('table'); // a refused value leaves the option as it was
    const patched = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }));
    expect(parameterOf(() => (patched.mode = 'bogus' as 'table'))).toBe('mode');
    patched.mode = 'fourier';
    expect(patched.mode).toBe('fourier');
  });

  it('recompiles only when the defines change: a light or polarisation in table mode keeps the program', () => {
    const m = new ThinFilmMaterial({ mode: 'table' });
    const key = m.customProgramCacheKey();
    const version = m.version;
    m.illuminant = 'D55';
    m.polarization = 's';
    expect([m.customProgramCacheKey(), m.version]).toEqual([key, version]);
    m.mode = 'exact';
    expect(m.customProgramCacheKey()).not.toBe(key);
    expect(m.version).toBeGreaterThan(version);
  });

  it("three's setValues sets them too", () => {
    const m = new ThinFilmMaterial();
    m.setValues({ mode: 'fourier' } as never);
    expect(m.mode).toBe('fourier');
  });
});

describe('the constructor and the API boundary', () => {
  it('takes the physical parameters and the options in one object, checking both', () => {
    const m = new ThinFilmMaterial({ iridescenceIOR: 1.4, roughness: 0.2, iridescence: 0.5, normalization: 'white' });
    expect([m.iridescenceIOR, m.roughness, m.iridescence, m.normalization]).toEqual([1.4, 0.2, 0.5, 'white']);
    expect(parameterOf(() => new ThinFilmMaterial({ iridescenceThicknessMaximum: 30_000 }))).toBe('iridescenceThicknessMaximum');
    expect(parameterOf(() => new ThinFilmMaterial({ iridescenceIOR: 5 }))).toBe('iridescenceIOR');
    expect(parameterOf(() => new ThinFilmMaterial({ mode: 'bogus' as 'table' }))).toBe('mode');
  });
});

describe('a base under the film', () => {
  it('takes a medium (a name, complex:n,k, a number, { complex }) in place of ior, refusing a bad one by name', () => {
    const m = new ThinFilmMaterial({ mode: 'fourier', base: 'Ti' });
    expect(m.base).toBe('Ti');
    m.base = 'complex:2.6,3.4';
    expect(m.base).toEqual({ complex: [2.6, 3.4] });
    m.base = { complex: [0.43, 2.455] };
    expect(m.base).toEqual({ complex: [0.43, 2.455] });
    m.base = null;
    expect(m.base).toBe(null);
    for (const bad of ['complex:2.6,-1', 'Unobtainium', 'complex:0,1'])
      expect(
        parameterOf(() => (m.base = bad)),
        bad,
      ).toBe('base');
  });

  it('draws the film over the base: a metal makes the shader opaque and tabulated, its uniforms the metal’s ñ', () => {
    const m = new ThinFilmMaterial({ iridescenceIOR: 1.38, mode: 'fourier', base: 'Au' });
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(shader.defines).toMatchObject({ TFC_OPAQUE_INSIDE: 1, TFC_DISPERSIVE: 1 });
    m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);
    const uniforms = shader.uniforms as Record<string, { value: number[] }>;
    // Gold at the sodium D line (589.3 nm) lies between Johnson & Christy's 548.6 nm (0.43 + 2.455i) and 582.1 nm (0.29 + 2.863i) rows… and the next, 616.8 nm (0.21 + 3.272i).
    const [n, k] = uniforms.uNInside!.value;
    expect(n! < 0.29 && n! > 0.21 && k! > 2.863 && k! < 3.272).toBe(true);
  });
});

describe('a film medium in place of iridescenceIOR', () => {
  it("takes a named film (TiO2 on Ti): dispersive, its uniform the film's ñ at the D line, a bad one refused by name", () => {
    const m = new ThinFilmMaterial({ mode: 'fourier', film: 'TiO2', base: 'Ti' });
    expect(m.film).toBe('TiO2');
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(shader.defines).toMatchObject({ TFC_OPAQUE_INSIDE: 1, TFC_DISPERSIVE: 1 });
    m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);
    // Sarkar et al.'s rows at 580 nm (2.149843) and 590 nm (2.145621) bracket the D line, 589.3 nm.
    const [n, k] = (shader.uniforms as Record<string, { value: number[] }>).uNFilm!.value;
    expect(n! > 2.145621 && n! < 2.149843 && k === 0).toBe(true);
    for (const bad of ['Unobtainium', 'complex:0,1'])
      expect(
        parameterOf(() => (m.film = bad)),
        bad,
      ).toBe('film');
  });
});

describe('a metal from its base colour', () => {
  const draw = (m: MeshPhysicalMaterial) =>
    m.onBeforeRender(null as never, new Scene(), null as never, null as never, null as never, null as never);

  it("puts the spectral film on the metallic lobe, over an opaque metal from color, and keeps three's dielectric one", () => {
    const m = new ThinFilmMaterial({ iridescenceIOR: 1.38, mode: 'fourier', metalness: 1, color: 0xffc356 });
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    expect(shader.defines).toMatchObject({ TFC_OPAQUE_INSIDE: 1, TFC_DISPERSIVE: 1 });
    expect(shader.fragmentShader).toContain('vec3 iridescenceFresnelMetallic = tfcSpectralIridescence(');
    expect(shader.fragmentShader).toContain('vec3 iridescenceFresnelDielectric = evalIridescence(');
    draw(m);
    const [n, k] = (shader.uniforms as Record<string, { value: number[] }>).uNInside!.value;
    // at 589.3 nm, between the green and the red channel: finite, and a metal (k > n, k > 1)
    expect(Number.isFinite(n) && Number.isFinite(k) && k! > n! && k! > 1).toBe(true);
  });

  it('asks three for a new program when metalness comes or goes, and takes an edge tint', () => {
    const m = new ThinFilmMaterial({ mode: 'fourier' });
    const key = m.customProgramCacheKey();
    draw(m);
    const version = m.version;
    m.metalness = 1;
    draw(m);
    expect(m.version).toBeGreaterThan(version);
    expect(m.customProgramCacheKey()).not.toBe(key);
    m.edgeTint = [1, 1, 1];
    expect(m.edgeTint).toEqual([1, 1, 1]);
    for (const bad of [[1, 2, 0], 'red', -1, [0.5, 0.5]])
      expect(
        parameterOf(() => (m.edgeTint = bad as never)),
        String(bad),
      ).toBe('edgeTint');
  });
});

describe("a scene's environment", () => {
  const drawIn = (m: MeshPhysicalMaterial, scene: Scene) =>
    m.onBeforeRender(null as never, scene, null as never, null as never, null as never, null as never);
  const compiled = (m: MeshPhysicalMaterial) => {
    const shader = shaderObject();
    m.onBeforeCompile(shader as never, null as never);
    return shader;
  };

  it("is reflected through the film's matrix: drawn in a scene with one, a new program with three planes and the light after three's; without, one plane again", () => {
    const m = new ThinFilmMaterial({ mode: 'fourier', lightTint: [1, 0.5, 0.2] });
    const lit = new Scene();
    lit.environment = new Texture();
    drawIn(m, new Scene());
    const plain = compiled(m);
    expect(plain.defines).not.toHaveProperty('TFC_ENVIRONMENT_MATRIX');
    const [version, key] = [m.version, m.customProgramCacheKey()];
    drawIn(m, lit);
    expect(m.version).toBeGreaterThan(version);
    expect(m.customProgramCacheKey()).not.toBe(key);
    const matrix = compiled(m);
    expect(matrix.defines).toHaveProperty('TFC_ENVIRONMENT_MATRIX', 1);
    expect(matrix.fragmentShader).toContain('reflectedLight.indirectSpecular += tfcEnvironmentThroughMatrix( radiance, iblIrradiance');
    // Its tint is a uniform then (the planes are the untinted light's), its table's three planes too.
    drawIn(m, lit);
    const u = matrix.uniforms as Record<string, { value: unknown }>;
    expect((u.uLightTint!.value as Vector3).toArray()).toEqual([1, 0.5, 0.2]);
    expect(u).toHaveProperty('uFilmTable2');
    // The material's own envMap counts as the scene's.
    const version2 = m.version;
    m.envMap = new Texture();
    drawIn(m, new Scene());
    expect(m.version).toBe(version2);
    m.envMap = null;
    drawIn(m, new Scene());
    expect(m.version).toBeGreaterThan(version2);
    expect(m.customProgramCacheKey()).toBe(key);
  });
});

describe('the quality knobs', () => {
  it('merges what is given over the defaults, the table knob by knob', () => {
    const q = filmQualityFrom({ exactSpectralBins: 45, table: { rows: 64 } });
    expect(q).toEqual({ ...DEFAULT_FILM_QUALITY, exactSpectralBins: 45, table: { ...DEFAULT_FILM_QUALITY.table, rows: 64 } });
    expect(filmQualityFrom()).toEqual(DEFAULT_FILM_QUALITY);
  });

  it.each([
    ['exactSpectralBins', { exactSpectralBins: 7 }], // 450 / 7 is not whole
    ['exactSpectralBins', { exactSpectralBins: 0 }],
    ['exactSpectralBins', { exactSpectralBins: 900 }],
    ['dispersiveSpectralBins', { dispersiveSpectralBins: 2.5 }],
    ['table.spectralBins', { table: { spectralBins: 100 } }],
    ['table.width', { table: { width: 100.5 } }],
    ['table.width', { table: { width: 32 } }],
    ['table.rows', { table: { rows: 1 } }],
    ['table.thickEndCellNm', { table: { thickEndCellNm: 0 } }],
    ['table.thicknessPower', { table: { thicknessPower: Number.NaN } }],
    ['table.cosPower', { table: { cosPower: 0.5 } }],
    ['table.fill', { table: { fill: 'spline' } }],
    ['tablePrecision', { tablePrecision: 'double' }],
    ['spectralTailTolerance', { spectralTailTolerance: -1e-6 }],
    ['airySeriesMaxOrders', { airySeriesMaxOrders: 0 }],
  ])('refuses quality.%s %j by name', (name, value) => {
    expect(() => filmQualityFrom(value as never)).toThrow(
      new RegExp(`^quality\\.${name.replace('.', '\\.')}: .* is not allowed; expected `),
    );
    expect(parameterOf(() => new ThinFilmMaterial({ quality: value as never }))).toBe(`quality.${name}`);
  });

  it('takes every whole divisor of 450 as a bin count', () => {
    for (const bins of [1, 2, 3, 5, 9, 10, 15, 18, 25, 30, 45, 50, 75, 90, 150, 225, 450])
      expect(filmQualityFrom({ exactSpectralBins: bins }).exactSpectralBins).toBe(bins);
  });
});

/**
 * The WebGPU entry as a three.js user meets it, in Node (node materials need no GPU to be made):
 * its options checked as the WebGL entry's, its properties, the program key they move, its glTF
 * upgrade, and the hooks a classic material's node copy takes.
 */
import { Group, Mesh, MeshPhysicalMaterial, MeshStandardMaterial, BoxGeometry } from 'three';
import { MeshPhysicalNodeMaterial } from 'three/webgpu';
import { beforeAll, describe, expect, it, vi } from 'vitest';
import { ParameterError } from '../../../src/input/validate.ts';
import { isSpectralIridescence } from '../../../src/meshMaterial/spectralFilm.ts';
import { spectralIridescence, useSpectralIridescence, whenSpectralReady } from '../../../src/nodeMaterial/spectralNodeMaterial.ts';
import { nodeDrawing } from '../../../src/nodeMaterial/spectralNodeDrawing.ts';

const film = () => new MeshPhysicalNodeMaterial({ iridescence: 1, iridescenceIOR: 1.33, iridescenceThicknessMaximum: 450 });

describe('the WebGPU entry, before its drawing is loaded', () => {
  it("draws three's film in a program of its own; the drawing's arrival moves the version and the key to the film's", async () => {
    vi.resetModules();
    const entry = await import('../../../src/nodeMaterial/spectralNodeMaterial.ts');
    const m = entry.spectralIridescence(film(), { mode: 'exact' });
    const [version, key] = [m.version, m.customProgramCacheKey()];
    expect(key).toMatch(/spectral-iridescence \S+ loading$/);
    m.polarization = 's';
    await entry.whenSpectralReady(m);
    expect(m.version).toBeGreaterThan(version);
    expect(m.customProgramCacheKey()).not.toBe(key);
    expect(m.customProgramCacheKey()).not.toMatch(/loading/);
  });
});

describe('the WebGPU entry', () => {
  beforeAll(() => nodeDrawing.load());

  it('checks its options as the WebGL entry does: a bad one is a ParameterError naming it, and nothing is changed', () => {
    const cases: readonly (readonly [string, object])[] = [
      ['mode', { mode: 'series' }],
      ['illuminant', { illuminant: 'D50' }],
      ['lightTint', { lightTint: [1, 2, 0] }],
      ['polarization', { polarization: 'q' }],
      ['base', { base: 'unobtainium' }],
      ['layers', { layers: '(1.4:10)*65' }],
    ];
    for (const [name, options] of cases) {
      const m = film();
      expect(() => spectralIridescence(m, options as never), name).toThrow(ParameterError);
      expect(() => spectralIridescence(m, options as never), name).toThrow(new RegExp(`^${name}`));
      expect(isSpectralIridescence(m), name).toBe(false);
    }
    expect(() => spectralIridescence(new MeshPhysicalNodeMaterial({ iridescence: 1, iridescenceIOR: 5 }))).toThrow(/iridescenceIOR/);
  });

  it('holds its options as properties; a change of program moves the version and the program key, a change back restores the key', () => {
    const m = spectralIridescence(film());
    expect(m.mode).toBe('table');
    const [version, key] = [m.version, m.customProgramCacheKey()];
    m.mode = 'exact';
    expect(m.version).toBeGreaterThan(version);
    expect(m.customProgramCacheKey()).not.toBe(key);
    m.mode = 'table';
    expect(m.customProgramCacheKey()).toBe(key);
    expect(() => (m.polarization = 'x' as never)).toThrow(/polarization/);
    expect(m.polarization).toBe('unpolarized');
  });

  it('drawn from the table, its light and polarisation are the texels: a change of them keeps the program; by exact, a change of polarisation does not', () => {
    const m = spectralIridescence(film());
    const [version, key] = [m.version, m.customProgramCacheKey()];
    m.illuminant = 'D93';
    m.polarization = 's';
    m.film = 'water';
    expect([m.version, m.customProgramCacheKey()]).toEqual([version, key]);
    m.mode = 'exact';
    const exactKey = m.customProgramCacheKey();
    m.polarization = 'p';
    expect(m.customProgramCacheKey()).not.toBe(exactKey);
  });

  it("keys each material's program apart, even where two hold the same options and the same 0/1 reduction of three's numbers", () => {
    // three shares the nodes built for the first material of a key among all of that key; the
    // film's uniforms and table are nodes of that build, so a shared key would draw the second
    // material with the first's film (iridescenceIOR 1.8 drawn as 1.33).
    const [a, b] = [1.33, 1.8].map((n) => spectralIridescence(new MeshPhysicalNodeMaterial({ iridescence: 1, iridescenceIOR: n })));
    expect(a!.customProgramCacheKey()).not.toBe(b!.customProgramCacheKey());
  });

  it("upgrades a loaded scene's iridescent physical materials, classic or node, and gives a classic one the lighting model its node copy takes", () => {
    const root = new Group();
    const classic = new MeshPhysicalMaterial({ iridescence: 1 });
    const node = film();
    const plain = new MeshPhysicalMaterial();
    const box = new BoxGeometry();
    root.add(new Mesh(box, classic), new Mesh(box, [node, plain]), new Mesh(box, new MeshStandardMaterial()));
    expect(useSpectralIridescence(root, { mode: 'exact' })).toEqual([classic, node]);
    expect([classic, node, plain].map(isSpectralIridescence)).toEqual([true, true, false]);
    // WebGPURenderer's node copy of a classic material takes its enumerable keys (NodeLibrary.fromMaterial).
    const copy: Record<string, unknown> = {};
    for (const k in classic) copy[k] = (classic as unknown as Record<string, unknown>)[k];
    expect(typeof copy.setupLightingModel).toBe('function');
  });

  it('draws `fourier` from the table, saying so', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const m = spectralIridescence(film(), { mode: 'fourier' });
    m.illuminant = 'D93';
    expect(warn.mock.calls.map((c) => String(c[0])).filter((t) => t.includes('mode fourier is drawn from the table'))).toHaveLength(1);
    warn.mockRestore();
  });

  it('whenSpectralReady resolves for `exact` at once and refuses a material that is not spectral', async () => {
    await expect(whenSpectralReady(spectralIridescence(film(), { mode: 'exact' }))).resolves.toBeUndefined();
    await expect(whenSpectralReady(film())).rejects.toThrow(ParameterError);
    await expect(whenSpectralReady(film())).rejects.toMatchObject({
      parameter: 'material',
      message: expect.stringMatching(/not spectral/) as unknown,
    });
  });
});

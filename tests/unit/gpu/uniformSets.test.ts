/**
 * Each uniform set is declared once and set by one factory: for every shader the product draws
 * with, the uniforms its GLSL declares in a configuration (the text a compiler sees with that
 * configuration's defines) are uniforms its material sets, and across every configuration the
 * material sets no uniform that no configuration declares. And no uniform is declared in two
 * files of shaders/, apart from the alternative members of one registry (each field's or method's
 * own GLSL, of which a program holds one). The flow's passes and the table pass are held the same
 * way beside their own code (tests/unit/gpuFilmDynamics/flowUniforms.test.ts, tests/unit/film/tablePassPrograms.test.ts).
 */
import { readFileSync, readdirSync } from 'node:fs';
import { MeshPhysicalMaterial, Scene, ShaderLib, type ShaderMaterial, Texture } from 'three';
import { describe, expect, it } from 'vitest';
import { createBubbleMaterial } from '../../../src/bubbleMaterials/bubbleMaterial.ts';
import { createBackgroundMaterial, environmentDefines } from '../../../src/bubbleMaterials/environmentMaterial.ts';
import { ENVIRONMENTS } from '../../../src/environments/environments.ts';
import { FIELDS } from '../../../src/fields/fields.ts';
import { FILM_METHODS } from '../../../src/methods/methods.ts';
import { spectralIridescence } from '../../../src/meshMaterial/spectralIridescence.ts';
import { loadDrawing } from '../../../src/meshMaterial/spectralDrawing.ts';
import { MODES } from '../../../src/settings/filmSettings.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { preprocessed } from '../../../scripts/harness/glslPreprocessor.ts';
import { declaredUniforms } from './glslUniforms.ts';

/** A constant film, a dispersive one, a film on a metal: the media pick what a shader reads. */
const MEDIA = [
  { nFilm: 1.33, nInside: 1 },
  { nFilm: 'water', nInside: 1 },
  { nFilm: 1.38, nInside: 'Au' },
] as const;

/** Every environment: the registry's names and a uniform colour. */
const EVERY_ENVIRONMENT = [...ENVIRONMENTS, { color: [1, 0.2, 0.2] } as const];

/** Stacks of films: one that follows the field's thickness over a dispersive inside, one of fixed layers. */
const STACKS = [
  {
    nFilm: 1.33,
    nInside: 'water',
    layers: [
      { n: 1.68, thicknessNm: 'd' },
      { n: 'TiO2', thicknessNm: 30 },
    ],
  },
  { nFilm: 1.33, nInside: 1.52, layers: [{ n: 1.38, thicknessNm: 99.6 }] },
] as const;

/** For each configuration of a material: the uniforms its shaders declare there. */
function declaredByConfiguration(materials: readonly Pick<ShaderMaterial, 'defines' | 'vertexShader' | 'fragmentShader'>[]): string[][] {
  return materials.map((m) => declaredUniforms(preprocessed(`${m.vertexShader}\n${m.fragmentShader}`, m.defines ?? {})));
}

/** Every uniform a configuration declares is set, and every uniform set is declared in some configuration. */
function expectDeclaredAreSet(declared: readonly string[][], set: readonly string[]): void {
  expect(declared.length).toBeGreaterThan(0);
  for (const names of declared) expect(names.filter((n) => !set.includes(n))).toEqual([]);
  expect([...new Set(declared.flat())].sort()).toEqual([...set].sort());
}

describe('uniform sets', () => {
  it('the preprocessing keeps the branches taken, include guards and all', () => {
    const glsl = [
      '#ifndef G',
      '#define G',
      'uniform float uA;',
      '#endif',
      '#ifndef G',
      'uniform float uRepeat;',
      '#endif',
      '#if M == M_B',
      'uniform float uB;',
      '#elif M == M_C || defined(X)',
      'uniform float uC;',
      '#else',
      'uniform float uD;',
      '#endif',
    ].join('\n');
    expect(declaredUniforms(preprocessed(glsl, { M: 2, M_B: 1, M_C: 2 }))).toEqual(['uA', 'uC']);
    expect(declaredUniforms(preprocessed(glsl, { M: 1, M_B: 1, M_C: 2 }))).toEqual(['uA', 'uB']);
    expect(declaredUniforms(preprocessed(glsl, { M: 0, M_B: 1, M_C: 2 }))).toEqual(['uA', 'uD']);
    expect(declaredUniforms(preprocessed(glsl, { M: 0, M_B: 1, M_C: 2, X: '' }))).toEqual(['uA', 'uC']);
  });

  it('the bubble sets what it declares, for every method, field, environment, kind of medium and stack', () => {
    const materials: ShaderMaterial[] = [];
    let set: string[] = [];
    for (const mode of FILM_METHODS)
      for (const field of FIELDS)
        for (const env of EVERY_ENVIRONMENT)
          for (const media of [...MEDIA, ...STACKS]) {
            const m = createBubbleMaterial({ ...DEFAULT_SETTINGS, mode, field, env, ...media }, DEFAULT_FILM_QUALITY);
            set = Object.keys(m.uniforms);
            materials.push(m);
          }
    expectDeclaredAreSet(declaredByConfiguration(materials), set);
  });

  it('the background sets what it declares, for every environment', () => {
    const materials = EVERY_ENVIRONMENT.map((env) => Object.assign(createBackgroundMaterial(), { defines: environmentDefines({ env }) }));
    expectDeclaredAreSet(declaredByConfiguration(materials), Object.keys(materials[0]!.uniforms));
  });

  it("the spectral iridescence adds to three's shader the uniforms it declares there, for every mode, kind of medium and stack, in a scene with an environment and without", async () => {
    // The film's drawing is a chunk of its own: loaded here, the materials' programs hold the film (else three's).
    await loadDrawing();
    const threes = declaredUniforms(ShaderLib.physical.fragmentShader);
    const declared: string[][] = [];
    let set: string[] = [];
    const lit = new Scene();
    lit.environment = new Texture();
    for (const scene of [new Scene(), lit])
      for (const mode of MODES)
        for (const media of [...MEDIA, ...STACKS]) {
          const layers = 'layers' in media ? media.layers : [];
          // Drawn first in `exact` (which reads no table, so no renderer is needed), the film follows the scene's environment.
          const m = spectralIridescence(new MeshPhysicalMaterial({ iridescence: 1 }), {
            mode: 'exact',
            film: media.nFilm,
            base: media.nInside,
            layers,
          });
          m.onBeforeRender(null as never, scene, null as never, null as never, null as never, null as never);
          (m as MeshPhysicalMaterial & { mode: string }).mode = mode;
          const shader = { fragmentShader: ShaderLib.physical.fragmentShader, vertexShader: '', uniforms: {}, defines: {} };
          m.onBeforeCompile(shader as never, null as never);
          // What three defines for a physical material with iridescence, beside the film's own defines.
          const defines = { STANDARD: '', PHYSICAL: '', USE_IRIDESCENCE: '', ...shader.defines };
          declared.push(declaredUniforms(preprocessed(shader.fragmentShader, defines)).filter((n) => !threes.includes(n)));
          set = Object.keys(shader.uniforms);
        }
    expect(declared.every((names) => names.length > 0)).toBe(true);
    expectDeclaredAreSet(declared, set);
  });

  it('no uniform is declared in two files of shaders/, but by the alternative members of one registry', () => {
    const dir = new URL('../../../shaders/', import.meta.url);
    const files = readdirSync(dir, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.glsl'));
    /** The folders whose files are alternatives: a program holds one field's and one method's GLSL. */
    const alternatives = ['fields/', 'methods/'];
    const declaredIn = new Map<string, string[]>();
    for (const file of files)
      for (const name of declaredUniforms(readFileSync(new URL(file, dir), 'utf8')))
        declaredIn.set(name, [...(declaredIn.get(name) ?? []), file]);
    const twice = [...declaredIn].filter(([, where]) => where.length > 1 && !alternatives.some((a) => where.every((f) => f.startsWith(a))));
    expect(declaredIn.size).toBeGreaterThan(20);
    expect(twice).toEqual([]);
  });
});

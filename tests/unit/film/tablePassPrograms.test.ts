/**
 * The table pass's programs: its material sets exactly the uniforms its assembled GLSL declares
 * (parsed from the GLSL, the independent side: a uniform declared and never set reads 0 on the
 * GPU), the grid's set exactly those filmTableGrid.glsl declares; one material per set of defines,
 * KEPT_PASSES at most, the polarisation a uniform.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { declaredUniforms } from '../gpu/glslUniforms.ts';
import { filmTableGridUniforms } from '../../../src/film/filmTableGrid.ts';
import { KEPT_PASSES } from '../../../src/film/keptPasses.ts';
import { TablePassPrograms } from '../../../src/film/tablePassPrograms.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';

const CONSTANT = { nFilm: 1.33, nInside: 1 } as const;
const DISPERSIVE = { nFilm: 'water', nInside: 1 } as const;
const METAL = { nFilm: 1.38, nInside: 'Au' } as const;
const STACK = {
  nFilm: 'water',
  nInside: 1.52,
  layers: [
    { n: 2.35, thicknessNm: 56.6 },
    { n: 1.46, thicknessNm: 'd' },
  ],
} as const;

describe('the table pass programs', () => {
  it('the pass sets exactly the uniforms filmTable.glsl declares, includes and all', () => {
    const material = new TablePassPrograms(DEFAULT_FILM_QUALITY).material(DISPERSIVE);
    const declared = declaredUniforms(material.fragmentShader).sort();
    expect(declared).toContain('uAirySeriesRows');
    expect(Object.keys(material.uniforms).sort()).toEqual(declared);
  });

  it("the grid's factory sets exactly what filmTableGrid.glsl declares", () => {
    const glsl = readFileSync(new URL('../../../shaders/film/filmTableGrid.glsl', import.meta.url), 'utf8');
    expect(Object.keys(filmTableGridUniforms()).sort()).toEqual(declaredUniforms(glsl).sort());
  });

  it('one material per set of defines, the last used first, KEPT_PASSES at most; the polarisation picks none', () => {
    const programs = new TablePassPrograms(DEFAULT_FILM_QUALITY);
    const constant = programs.material(CONSTANT);
    expect(programs.material({ ...CONSTANT })).toBe(constant);
    const sPolarized = { ...CONSTANT, polarization: 's' as const };
    expect(programs.key(sPolarized)).toBe(programs.key(CONSTANT));
    const dispersive = programs.material(DISPERSIVE);
    expect(dispersive).not.toBe(constant);
    expect(programs.key(DISPERSIVE)).not.toBe(programs.key(CONSTANT));
    expect(KEPT_PASSES).toBe(2); // what follows assumes it
    // A third set takes the least recently used material (the constant film's), given its defines.
    const metal = programs.material(METAL);
    expect(metal).toBe(constant);
    expect(metal.defines).toHaveProperty('TFC_OPAQUE_INSIDE', 1);
    expect(programs.material(DISPERSIVE)).toBe(dispersive);
  });

  it("a stack of films takes the recursion's program: its layers' defines, not a dispersive film's, and the finer bins", () => {
    const programs = new TablePassPrograms(DEFAULT_FILM_QUALITY);
    const stack = programs.material(STACK);
    expect(stack.defines).toHaveProperty('TFC_FILM_LAYERS', 1);
    expect(stack.defines).not.toHaveProperty('TFC_DISPERSIVE');
    expect(stack.defines).toHaveProperty('TFC_SPECTRAL_BINS', DEFAULT_FILM_QUALITY.dispersiveSpectralBins);
    // The layers are a texture: another stack of as many or more layers takes the same program.
    expect(programs.key({ ...STACK, layers: [...STACK.layers, ...STACK.layers] })).toBe(programs.key(STACK));
    expect(programs.material(CONSTANT).defines).not.toHaveProperty('TFC_FILM_LAYERS');
  });
});

/**
 * The flow's texture layouts by name: the GLSL of shaders/gpuFilmDynamics/ reads every layout define that
 * src/gpuFilmDynamics/flowLayouts.ts emits from its tables, reads no TFC_ name the passes are not given, and
 * adds no bare number to a name (an offset into a layout); the tables place each part once.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { HOLE_RAYS } from '../../../src/physics/filmDynamics/filmHoles.ts';
import { HOLE_FRAME, HOLE_TABLE, flowLayoutDefines, holeFrameTexel } from '../../../src/gpuFilmDynamics/flowLayouts.ts';
import { flowPassDefines } from '../../../src/gpuFilmDynamics/flowPasses.ts';

const flowDir = new URL('../../../shaders/gpuFilmDynamics/', import.meta.url);
const flowGlsl = readdirSync(flowDir)
  .filter((f) => f.endsWith('.glsl'))
  .map((file) => ({ file, text: readFileSync(new URL(file, flowDir), 'utf8') }));
/** The GLSL without its comments: what a compiler reads. */
const code = (text: string): string => text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/.*$/gm, '');
const namesIn = (text: string): string[] => code(text).match(/\bTFC_[A-Z0-9_]+\b/g) ?? [];
/** A TFC_ name with a bare number added or taken away, on either side. */
const OFFSET = /\bTFC_[A-Z0-9_]+\s*[-+]\s*\d|\d\s*[-+]\s*TFC_[A-Z0-9_]+/;

describe('flow layouts', () => {
  const defines = flowLayoutDefines();

  it("the hole table's frame lies after the rays, each part in its own texel inside the row", () => {
    const texels = HOLE_FRAME.map(holeFrameTexel);
    expect(new Set(texels).size).toBe(HOLE_FRAME.length);
    expect(Math.min(...texels)).toBe(HOLE_RAYS);
    expect(Math.max(...texels)).toBe(HOLE_TABLE.width - 1);
    expect(HOLE_FRAME.map((part) => defines[`TFC_HOLE_${part.toUpperCase()}_TEXEL`])).toEqual(texels);
  });

  it('the GLSL reads every layout define, and no TFC_ name the passes are not given or it does not declare', () => {
    const read = new Set(flowGlsl.flatMap(({ text }) => namesIn(text)));
    expect(Object.keys(defines).filter((name) => !read.has(name))).toEqual([]);
    // Constants of shaders/gpuFilmDynamics/, and the texel records' macros (shaders/gpu/texelRecord.glsl).
    const declared = new Set([
      ...flowGlsl.flatMap(({ text }) => [...code(text).matchAll(/\bconst\s+\w+\s+(TFC_[A-Z0-9_]+)/g)].map((m) => m[1]!)),
      ...[...readFileSync(new URL('../gpu/texelRecord.glsl', flowDir), 'utf8').matchAll(/#define\s+(TFC_[A-Z0-9_]+)/g)].map((m) => m[1]!),
    ]);
    const given = Object.keys(flowPassDefines());
    expect([...read].filter((name) => !given.includes(name) && !declared.has(name))).toEqual([]);
  });

  it('the GLSL places no texel or channel at a bare offset from a name', () => {
    const offsets = flowGlsl.flatMap(({ file, text }) =>
      code(text)
        .split('\n')
        .flatMap((line, i) => (OFFSET.test(line) ? [`${file}:${i + 1}: ${line.trim()}`] : [])),
    );
    expect(offsets).toEqual([]);
  });

  it('the offset check finds a bare offset', () => {
    expect(OFFSET.test('texelFetch(holes, ivec2(TFC_HOLE_RAYS + 1, s), 0)')).toBe(true);
    expect(OFFSET.test('ivec2(2 - TFC_HOLE_RAYS, s)')).toBe(true);
    expect(OFFSET.test('texelFetch(holes, ivec2(TFC_HOLE_E1_TEXEL, s), 0); ivec2((k + 1) % TFC_HOLE_RAYS, s)')).toBe(false);
  });
});

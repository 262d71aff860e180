/**
 * The flow's texels by name: every texture and target of the flow is a texel record of
 * src/gpuFilmDynamics/flowTexels.ts, one texel each, and the GLSL that reads them (shaders/gpuFilmDynamics/, and the
 * bubble's flow field that samples the padded film) reads no texel by position: no swizzle and no
 * constant index of a vec4, so a texel's fields are reached through the records' macros at their
 * defines only, and reordering a record's fields cannot change what is drawn.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { packTexelRecord } from '../../../src/gpu/texelRecord.ts';
import { FLOW_TEXELS, SURFACTANT_SWEEP, SWEEP_GUESS, SWEEP_PREVIOUS_GUESS, ZERO_GUESS } from '../../../src/gpuFilmDynamics/flowTexels.ts';
import { flowPassDefines } from '../../../src/gpuFilmDynamics/flowPasses.ts';

const shaderDir = new URL('../../../shaders/', import.meta.url);
/** The GLSL that reads the flow's texels. */
const FILES = [
  ...readdirSync(new URL('gpuFilmDynamics/', shaderDir))
    .filter((f) => f.endsWith('.glsl'))
    .map((f) => `gpuFilmDynamics/${f}`),
  'fields/flowField.glsl',
];
const text = (file: string): string => readFileSync(new URL(file, shaderDir), 'utf8');
/** A line without its comment; block comments blanked, their lines kept. */
const code = (source: string): string[] =>
  source
    .replace(/\/\*[\s\S]*?\*\//g, (comment) => comment.replace(/[^\n]/g, ' '))
    .split('\n')
    .map((line) => line.replace(/\/\/.*$/, ''));

/** What marks a positional read kept on purpose: a comment on its line that says why. */
const KEPT = /\/\/ by position: \S/;
/** The most positional reads kept. */
const MAX_KEPT = 4;

/** A function's signature at the start of a line: its return type, name and parameters. */
const SIGNATURE = /^(\w+)\s+(\w+)\s*\(([^)]*)\)/;
/** A declaration of a variable or parameter: its type and name. */
const DECLARATION = /\b(\w+)\s+(\w+)\s*(?=[=;,)[])/g;

/** The functions of `lines` that return a vec4 (texelFetch and texture among them). */
function vec4Calls(lines: readonly string[]): Set<string> {
  const calls = new Set(['texelFetch', 'texture']);
  for (const line of lines) {
    const m = SIGNATURE.exec(line);
    if (m?.[1] === 'vec4') calls.add(m[2]!);
  }
  return calls;
}

/**
 * The vec4 values in scope on each line of `lines`: the uniforms, and in a function its
 * parameters and the variables declared before the line (a name is another type in another function).
 */
function vec4Values(lines: readonly string[]): Set<string>[] {
  const uniforms = new Set(lines.flatMap((line) => [...line.matchAll(/\buniform\s+vec4\s+(\w+)/g)].map((m) => m[1]!)));
  let local = new Map<string, string>();
  return lines.map((line) => {
    if (SIGNATURE.test(line)) local = new Map();
    for (const m of line.matchAll(DECLARATION)) local.set(m[2]!, m[1]!);
    return new Set([...uniforms, ...[...local].filter(([, type]) => type === 'vec4').map(([name]) => name)]);
  });
}

const SWIZZLE = /^\s*(?:\.\s*[xyzwrgbastpq]{1,4}\b|\[\s*\d+\s*\])/;

/** The end of the call whose opening parenthesis is at `open`. */
function closing(line: string, open: number): number {
  let depth = 0;
  for (let i = open; i < line.length; i++) {
    if (line[i] === '(') depth++;
    else if (line[i] === ')' && --depth === 0) return i;
  }
  return line.length;
}

/** The positional reads of a vec4 on a line: a vec4 value, or a call returning one, swizzled or indexed by a number. */
function positionalReads(line: string, values: Set<string>, calls: Set<string>): string[] {
  const found: string[] = [];
  for (const m of line.matchAll(/\b(\w+)\s*(\()?/g)) {
    const [name, call] = [m[1]!, m[2] !== undefined];
    const after = call ? line.slice(closing(line, m.index + m[0].length - 1) + 1) : line.slice(m.index + name.length);
    if ((call ? calls : values).has(name) && SWIZZLE.test(after))
      found.push(`${name}${call ? '(…)' : ''}${SWIZZLE.exec(after)![0].trim()}`);
  }
  return found;
}

/** Every positional read of the files: where, what, and whether it is kept on purpose. */
function allPositionalReads(): { at: string; read: string; kept: boolean }[] {
  const sources = FILES.map((file) => ({ file, raw: text(file).split('\n'), lines: code(text(file)) }));
  // A function of an included file is called in another.
  const calls = vec4Calls(sources.flatMap(({ lines }) => lines));
  return sources.flatMap(({ file, raw, lines }) => {
    const values = vec4Values(lines);
    return lines.flatMap((line, i) =>
      positionalReads(line, values[i]!, calls).map((read) => ({ at: `${file}:${i + 1}`, read, kept: KEPT.test(raw[i]!) })),
    );
  });
}

describe('flow texels', () => {
  it('are records of one texel each, whose defines are distinct and given to every pass', () => {
    const prefixes = FLOW_TEXELS.map((r) => r.prefix);
    expect(new Set(prefixes).size).toBe(FLOW_TEXELS.length);
    for (const r of FLOW_TEXELS) expect([r.prefix, r.texels]).toEqual([r.prefix, 1]);
    const defines = flowPassDefines();
    for (const r of FLOW_TEXELS)
      for (const field of Object.keys(r.fields))
        expect(defines[`${r.prefix}_${field}`], `${r.prefix}_${field}`).toBe(r.offsets[field as never]);
  });

  it("each sweep's guess picks the sweep's named field from a packed texel, and the first sweep's none", () => {
    const texel = new Float32Array(4);
    packTexelRecord(SURFACTANT_SWEEP, texel, 0, { X: 3, PREVIOUS_X: -5 });
    const dot = (mask: readonly number[]) => mask.reduce((sum, m, k) => sum + m * texel[k]!, 0);
    expect([dot(SWEEP_GUESS), dot(SWEEP_PREVIOUS_GUESS), dot(ZERO_GUESS)]).toEqual([3, -5, 0]);
  });

  it('are read by no swizzle or constant index in the GLSL, but a few kept and commented', () => {
    const reads = allPositionalReads();
    expect(reads.filter((r) => !r.kept).map((r) => `${r.at}: ${r.read}`)).toEqual([]);
    expect(reads.filter((r) => r.kept).length).toBeLessThanOrEqual(MAX_KEPT);
  });

  it('the check finds a swizzle or a constant index of a fetched texel, a vec4 or a call returning one, and passes a read by name', () => {
    const lines = [
      'vec4 tfcSamplePadded(sampler2D padded, vec3 p) {',
      'void f() {',
      '  vec4 filmA = texelFetch(uFilm, t, 0);',
      '  vec3 p;',
    ];
    const [values, calls] = [vec4Values(lines)[3]!, vec4Calls(lines)];
    for (const bad of [
      'if (filmA.b == 0.0) return;',
      'vec2 g = texelFetch(uFilm, tfcCellTexel(c), 0).rg;',
      'float eta = tfcSamplePadded(uFlowFilm, vec3(p.x, -p.z, p.y)).r;',
      'float w = filmA[3];',
    ])
      expect(positionalReads(bad, values, calls), bad).not.toEqual([]);
    for (const good of [
      'float eta = TFC_TEXEL_FLOAT(filmA, TFC_FLOW_FILM_ETA);',
      'TfcFilm film = tfcFilm(tfcSamplePadded(uFlowFilm, vec3(p.x, -p.z, p.y)));',
      'int e = tfcEdgeOf(filmA[s]);',
    ])
      expect(positionalReads(good, values, calls), good).toEqual([]);
    // In another function the name is another type.
    expect(vec4Values([...lines, 'void g(ivec2 filmA) {'])[4]!.has('filmA')).toBe(false);
  });
});

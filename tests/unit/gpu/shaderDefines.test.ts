/**
 * The project's shader defines carry the prefix TFC_, so none can collide with a define of
 * three.js (which prepends its own, e.g. USE_MAP, FLAT_SHADED, to every ShaderMaterial).
 */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { POLARIZATIONS } from '../../../src/physics/filmReflectance.ts';
import { bubbleDefines } from '../../../src/bubbleMaterials/bubbleMaterial.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { ENVIRONMENTS, FIELDS, FILM_METHODS, SIDES, SPACES } from '../../../src/settings/filmSettings.ts';
import { filmTableLayoutDefines } from '../../../src/film/filmTableDefines.ts';
import { spectralBinDefines } from '../../../src/film/spectralBinsTexture.ts';
import { airySeriesDefines } from '../../../src/film/spectralTransformTexture.ts';
import { AIRY_ROW } from '../../../src/film/airySeriesRows.ts';
import { DISPERSIVE_BIN } from '../../../src/film/dispersiveRows.ts';
import { MEDIA_KNOT } from '../../../src/film/filmMedia.ts';
import { FILM_LAYER } from '../../../src/film/filmStack.ts';
import { FLOW_TEXELS } from '../../../src/gpuFilmDynamics/flowTexels.ts';
import { type FieldWidth, texelRecordDefines } from '../../../src/gpu/texelRecord.ts';

const PREFIX = /^TFC_[A-Z0-9_]+$/;
/** Include guards (defined and tested only by their own file), and three.js's names that filmColor.glsl uses on purpose for the peer. */
const NOT_OURS = [/^THIN_FILM_[A-Z0-9_]+$/, /^USE_IRIDESCENCE$/, /^XYZ_TO_REC709$/];

const shaderDir = new URL('../../../shaders/', import.meta.url);
const shaders = readdirSync(shaderDir, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.glsl'));

/**
 * Every texel record TypeScript packs, with the texture (or uniform array) the shaders read it from;
 * the flow's, one texel each, are fetched whole and read through their GLSL's accessors
 * (tests/unit/gpuFilmDynamics/flowTexels.test.ts holds those to no read by position).
 */
const RECORDS = [
  { record: AIRY_ROW, texture: 'uAirySeriesRows' },
  { record: DISPERSIVE_BIN, texture: 'uDispersiveRows' },
  { record: MEDIA_KNOT, texture: 'uMediaKnots' },
  { record: FILM_LAYER, texture: 'uFilmLayers' },
  ...FLOW_TEXELS.map((record) => ({ record, texture: null })),
] as const;

/** Each record field's define and its width. */
const RECORD_FIELDS = new Map<string, FieldWidth>(
  RECORDS.flatMap(({ record }) =>
    Object.entries(record.fields as Record<string, FieldWidth>).map(([name, width]) => [`${record.prefix}_${name}`, width] as const),
  ),
);
const RECORD_TEXTURES = RECORDS.flatMap(({ texture }) => (texture === null ? [] : [texture]));
/** The macros of shaders/gpu/texelRecord.glsl that read or set a field at its offset, and the width each takes. */
const FIELD_MACRO = /\bTFC_(?:RECORD|TEXEL|SET_TEXEL)_(FLOAT|VEC2|VEC3|VEC4)\s*\(/g;
const MACRO_WIDTHS: Readonly<Record<string, FieldWidth>> = { FLOAT: 1, VEC2: 2, VEC3: 3, VEC4: 4 };

/** The text from `open` (an opening parenthesis) to its matching one, and what follows it. */
function parenthesised(text: string, open: number): { inside: string; after: string } {
  let depth = 0;
  for (let i = open; i < text.length; i++) {
    if (text[i] === '(') depth++;
    else if (text[i] === ')' && --depth === 0) return { inside: text.slice(open + 1, i), after: text.slice(i + 1) };
  }
  return { inside: text.slice(open + 1), after: '' };
}

/** `inside` split at its top-level commas. */
function topLevelArguments(inside: string): string[] {
  const args = [''];
  let depth = 0;
  for (const c of inside) {
    if (c === ',' && depth === 0) args.push('');
    else {
      if (c === '(' || c === '[') depth++;
      if (c === ')' || c === ']') depth--;
      args[args.length - 1] += c;
    }
  }
  return args.map((a) => a.trim());
}

const BARE_NUMBER = /(?<![A-Za-z_0-9.])\d/;
/** A swizzle or an index right after an expression: reading a packed texel by position. */
const BY_POSITION = /^\s*[.[]/;

/**
 * How a line of GLSL reads a texel record other than by its fields' names: a field macro
 * (TFC_RECORD_FLOAT, TFC_RECORD_VEC2) at an offset that is not a field's define or a field of
 * another width, a record's texel fetched at a bare offset, or fetched and then swizzled or indexed.
 */
function readsByPosition(line: string): string[] {
  if (/^\s*#\s*define\b/.test(line)) return [];
  const problems: string[] = [];
  for (const m of line.matchAll(FIELD_MACRO)) {
    const offset = topLevelArguments(parenthesised(line, m.index + m[0].length - 1).inside)[1] ?? '';
    const width = RECORD_FIELDS.get(offset);
    if (width === undefined) problems.push(`${m[0]}… at ${offset || 'no offset'}, not a field's name`);
    else if (width !== MACRO_WIDTHS[m[1]!]) problems.push(`${m[0]}… at ${offset}, a field of ${width} floats`);
  }
  for (const m of line.matchAll(/\btexelFetch\s*\(/g)) {
    const { inside, after } = parenthesised(line, m.index + m[0].length - 1);
    const [texture = '', coordinate = ''] = topLevelArguments(inside);
    if (!RECORD_TEXTURES.includes(texture as (typeof RECORD_TEXTURES)[number])) continue;
    if (BARE_NUMBER.test(coordinate)) problems.push(`${texture} fetched at ${coordinate}`);
    if (BY_POSITION.test(after)) problems.push(`${texture}'s texel read by position`);
  }
  for (const texture of RECORD_TEXTURES)
    for (const m of line.matchAll(new RegExp(`\\b${texture}\\s*\\[`, 'g'))) {
      const close = line.indexOf(']', m.index);
      if (close >= 0 && BY_POSITION.test(line.slice(close + 1))) problems.push(`${texture}'s element read by position`);
    }
  return problems;
}

describe('shader defines', () => {
  it('set by TypeScript all start with TFC_, for every mode, polarisation, field, wall, environment and space', () => {
    const keys = new Set<string>();
    for (const mode of FILM_METHODS)
      for (const polarization of POLARIZATIONS)
        for (const field of FIELDS)
          for (const sides of SIDES)
            for (const env of ENVIRONMENTS)
              for (const space of SPACES) {
                Object.keys(
                  bubbleDefines({ ...DEFAULT_SETTINGS, mode, polarization, field, sides, env, space }, DEFAULT_FILM_QUALITY),
                ).forEach((k) => keys.add(k));
              }
    const q = DEFAULT_FILM_QUALITY;
    for (const d of [
      spectralBinDefines(q.table.spectralBins, q.spectralTailTolerance),
      filmTableLayoutDefines(q.table),
      airySeriesDefines(2),
      ...RECORDS.map(({ record }) => texelRecordDefines(record)),
    ]) {
      Object.keys(d).forEach((k) => keys.add(k));
    }
    expect(keys.size).toBeGreaterThan(10);
    expect([...keys].filter((k) => !PREFIX.test(k))).toEqual([]);
  });

  it('read or defined in shaders/ all start with TFC_ (include guards and three.js names apart)', () => {
    const bad: string[] = [];
    for (const file of shaders) {
      const lines = readFileSync(new URL(file, shaderDir), 'utf8').split('\n');
      lines.forEach((line, i) => {
        const directive = /^\s*#\s*(if|ifdef|ifndef|elif|define|undef)\b(.*)$/.exec(line);
        if (!directive) return;
        // #define NAME value (or NAME(params) body): only NAME is a define; in conditions every identifier but `defined` is one.
        const body = directive[1] === 'define' ? (directive[2]!.trim().split(/[\s(]/)[0] ?? '') : directive[2]!;
        for (const name of body.match(/\b[A-Za-z_][A-Za-z0-9_]*\b/g) ?? []) {
          if (name === 'defined' || PREFIX.test(name) || NOT_OURS.some((r) => r.test(name))) continue;
          bad.push(`${file}:${i + 1}: ${name}`);
        }
      });
    }
    expect(shaders.length).toBeGreaterThan(10);
    expect(bad).toEqual([]);
  });

  it('compared in #if and #elif by name, never with a bare number (the TypeScript side emits every code)', () => {
    const bare: string[] = [];
    for (const file of shaders)
      readFileSync(new URL(file, shaderDir), 'utf8')
        .split('\n')
        .forEach((line, i) => {
          const condition = /^\s*#\s*(?:if|elif)\b(.*)$/.exec(line)?.[1];
          if (condition !== undefined && /(?<![A-Za-z_0-9])\d/.test(condition)) bare.push(`${file}:${i + 1}: ${line.trim()}`);
        });
    expect(bare).toEqual([]);
  });

  it('the bare-number check finds a number in a condition', () => {
    const condition = /^\s*#\s*(?:if|elif)\b(.*)$/.exec('#elif TFC_FILM_MODE == 2')![1]!;
    expect(/(?<![A-Za-z_0-9])\d/.test(condition)).toBe(true);
    expect(/(?<![A-Za-z_0-9])\d/.test(' TFC_FILM_MODE == TFC_FILM_MODE_TABLE2')).toBe(false);
  });
});

describe('texel records', () => {
  it("are read in shaders/ by their fields' names only, never at a bare offset or by a swizzle of a fetched texel", () => {
    const problems: string[] = [];
    for (const file of shaders)
      readFileSync(new URL(file, shaderDir), 'utf8')
        .split('\n')
        .forEach((line, i) => problems.push(...readsByPosition(line).map((p) => `${file}:${i + 1}: ${p}`)));
    expect(problems).toEqual([]);
  });

  it('have every field read or set by name in shaders/ (so none is read some other way)', () => {
    const text = shaders.map((file) => readFileSync(new URL(file, shaderDir), 'utf8')).join('\n');
    const unread = [...RECORD_FIELDS.keys()].filter(
      (name) => !new RegExp(`TFC_(RECORD|TEXEL|SET_TEXEL)_(FLOAT|VEC\\d)\\(\\s*\\w+\\s*,\\s*${name}\\s*[,)]`).test(text),
    );
    expect(RECORD_FIELDS.size).toBeGreaterThan(10);
    expect(unread).toEqual([]);
  });

  it('the check finds a read at a bare offset, by a swizzle or of the wrong width, and passes a read by name', () => {
    for (const bad of [
      'vec4 c = texelFetch(uAirySeriesRows, ivec2(2, y), 0);',
      'pathPerNm = texelFetch(uAirySeriesRows, ivec2(i, y), 0).z;',
      'vec4 t3 = texelFetch(uDispersiveRows, ivec2(TFC_DISPERSIVE_BIN_TEXELS * b + 3, y), 0);',
      'float n = uMediaKnots[i].x;',
      'float c0 = TFC_RECORD_FLOAT(r, 5);',
      'vec2 b = TFC_RECORD_VEC2(r, TFC_AIRY_ROW_C0_0);',
      'vec3 c = TFC_TEXEL_VEC3(t, TFC_FLOW_FILM_ETA);',
      'TFC_SET_TEXEL_FLOAT(t, 2, eta);',
    ])
      expect(readsByPosition(bad), bad).not.toEqual([]);
    expect(readsByPosition('r[i] = texelFetch(uAirySeriesRows, ivec2(i, y), 0);')).toEqual([]);
    expect(
      readsByPosition('t[0] = AirySeriesTerms(TFC_RECORD_FLOAT(r, TFC_AIRY_ROW_C0_0), TFC_RECORD_VEC2(r, TFC_AIRY_ROW_B_0), x);'),
    ).toEqual([]);
  });
});

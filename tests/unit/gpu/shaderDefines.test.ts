/**
 * The project's shader defines carry the prefix TFC_, so none can collide with a define of
 * three.js (which prepends its own, e.g. USE_MAP, FLAT_SHADED, to every ShaderMaterial).
 */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { POLARIZATIONS } from '../../../src/physics/filmReflectance.ts';
import { bubbleDefines } from '../../../src/bubble/bubbleMaterial.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { ENVIRONMENTS, FIELDS, FILM_METHODS, SIDES, SPACES } from '../../../src/settings/filmSettings.ts';
import { filmTableLayoutDefines } from '../../../src/film/filmTableDefines.ts';
import { spectralBinDefines } from '../../../src/film/spectralBinsTexture.ts';
import { airySeriesDefines } from '../../../src/film/spectralTransformTexture.ts';

const PREFIX = /^TFC_[A-Z0-9_]+$/;
/** Include guards (defined and tested only by their own file), and three.js's names that filmColor.glsl uses on purpose for the peer. */
const NOT_OURS = [/^THIN_FILM_[A-Z0-9_]+$/, /^USE_IRIDESCENCE$/, /^XYZ_TO_REC709$/];

const shaderDir = new URL('../../../shaders/', import.meta.url);
const shaders = readdirSync(shaderDir, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.glsl'));

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
        // #define NAME value: only NAME is a define; in conditions every identifier but `defined` is one.
        const body = directive[1] === 'define' ? (directive[2]!.trim().split(/\s+/)[0] ?? '') : directive[2]!;
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

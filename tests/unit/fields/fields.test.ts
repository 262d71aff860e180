/** The thickness fields: each module's uniforms are what its GLSL declares, and its range bounds its thickness. */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { FIELDS, THICKNESS_FIELDS } from '../../../src/fields/fields.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';

const shaders = new URL('../../../shaders/', import.meta.url);
/** A GLSL file by its name, which is unique across shaders/'s folders. */
const glsl = (file: string): string => {
  const path = readdirSync(shaders, { recursive: true, encoding: 'utf8' }).find((f) => f === file || f.endsWith(`/${file}`));
  if (!path) throw new Error(`shaders/ holds no ${file}`);
  return readFileSync(new URL(path, shaders), 'utf8');
};
/** The uniforms a field's GLSL declares, its includes' included. */
function declared(file: string): string[] {
  const text = glsl(file);
  const included = [...text.matchAll(/^#include "([^"]+)"/gm)].flatMap((m) => declared(m[1]!));
  return [...included, ...[...text.matchAll(/^uniform \w+ (\w+)/gm)].map((m) => m[1]!)];
}

describe('thickness fields', () => {
  it.each(FIELDS)('%s: its uniforms are exactly those its GLSL declares, and it defines tfcThicknessAt', (name) => {
    const field = THICKNESS_FIELDS[name];
    expect(Object.keys(field.uniforms()).sort()).toEqual(declared(field.glsl).sort());
    expect(glsl(field.glsl)).toMatch(/^float tfcThicknessAt\(vec3 p\)/m);
  });

  it.each(FIELDS)('%s: never thicker than its maximum, at points all over the sphere and over time', (name) => {
    const field = THICKNESS_FIELDS[name];
    for (const s of [DEFAULT_SETTINGS, { ...DEFAULT_SETTINGS, thicknessNm: 3000, thicknessRangeNm: 5000, timeSeconds: 37 }]) {
      const max = field.maxThicknessNm(s);
      for (let i = 0; i < 400; i++) {
        const y = -1 + (2 * i) / 399;
        const r = Math.sqrt(1 - y * y);
        const azimuth = 2.399963 * i; // the golden angle: points spread over the sphere
        const d = field.thicknessAt([r * Math.cos(azimuth), y, r * Math.sin(azimuth)], s);
        expect(d).toBeGreaterThanOrEqual(0);
        expect(d).toBeLessThanOrEqual(max + 1e-9);
      }
    }
  });
});

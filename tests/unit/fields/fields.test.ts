/** The thickness fields: each module's uniforms are what its GLSL declares, and its range bounds its thickness. */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { FIELDS, THICKNESS_FIELDS, settingApplies } from '../../../src/fields/fields.ts';
import type { FieldSettings, ThicknessField } from '../../../src/fields/thicknessField.ts';
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

/** Another valid value of each setting a field may read than the default's (DEFAULT_SETTINGS). */
const OTHER_VALUE: { readonly [K in keyof FieldSettings]: FieldSettings[K] } = {
  thicknessNm: 300,
  thicknessRangeNm: 300,
  swirlSpeed: 2,
  timeSeconds: 37,
  radiusMm: 20,
  surfactantMolM2: 2e-7,
  evaporationNmS: 5,
  windMps: 1,
  windTurnDegS: 20,
  seed: 7,
  simSpeed: 2,
  gridN: 64,
  renew: false,
};

/** Points spread over the sphere (the golden angle in azimuth), from the bottom to the top. */
const SPHERE_POINTS = Array.from({ length: 400 }, (_, i) => {
  const y = -1 + (2 * i) / 399;
  const r = Math.sqrt(1 - y * y);
  const azimuth = 2.399963 * i;
  return [r * Math.cos(azimuth), y, r * Math.sin(azimuth)] as const;
});

/** Everything a field computes from the settings: its thickness over the sphere, its maximum, its uniforms. */
function computed(field: ThicknessField, s: FieldSettings) {
  const uniforms = field.uniforms();
  field.update(uniforms, s);
  return { thickness: SPHERE_POINTS.map((p) => field.thicknessAt(p, s)), max: field.maxThicknessNm(s), uniforms };
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
      for (const p of SPHERE_POINTS) {
        const d = field.thicknessAt(p, s);
        expect(d).toBeGreaterThanOrEqual(0);
        expect(d).toBeLessThanOrEqual(max + 1e-9);
      }
    }
  });

  it.each(FIELDS)(
    '%s: a setting it does not read (another field reads it) changes nothing it computes, so the panel may hide it',
    (name) => {
      const field = THICKNESS_FIELDS[name];
      const start = computed(field, DEFAULT_SETTINGS);
      const others = (Object.keys(OTHER_VALUE) as (keyof FieldSettings)[]).filter((key) => !settingApplies(key, name));
      for (const key of others) expect(computed(field, { ...DEFAULT_SETTINGS, [key]: OTHER_VALUE[key] }), key).toEqual(start);
    },
  );

  it('each setting a uniform, drained or swirling film reads changes its thickness somewhere', () => {
    const moving = { ...DEFAULT_SETTINGS, timeSeconds: 5 };
    for (const name of FIELDS.filter((f) => !THICKNESS_FIELDS[f].evolves)) {
      const field = THICKNESS_FIELDS[name];
      expect(field.reads.length).toBeGreaterThan(0);
      for (const key of field.reads)
        expect(computed(field, { ...moving, [key]: OTHER_VALUE[key] }).thickness, `${name} ${key}`).not.toEqual(
          computed(field, moving).thickness,
        );
    }
  });

  it('the flowing film reads its thickness, the time it is simulated to and every setting of its own, and none of the swirl', () => {
    expect([...THICKNESS_FIELDS.flow.reads].sort()).toEqual(
      [
        'thicknessNm',
        'timeSeconds',
        'radiusMm',
        'surfactantMolM2',
        'evaporationNmS',
        'windMps',
        'windTurnDegS',
        'seed',
        'simSpeed',
        'gridN',
        'renew',
      ].sort(),
    );
    expect(settingApplies('swirlSpeed', 'flow')).toBe(false);
    expect(settingApplies('thicknessRangeNm', 'flow')).toBe(false);
    // A setting no field reads is not a field's: it applies under every field.
    for (const name of FIELDS) expect(settingApplies('exposure', name)).toBe(true);
  });
});

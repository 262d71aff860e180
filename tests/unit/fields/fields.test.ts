/** The thickness fields: each module's uniforms are what its GLSL declares, and its range bounds its thickness. */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  FIELDS,
  FIELD_SETTINGS,
  type FieldName,
  type FieldSettings,
  THICKNESS_FIELDS,
  drawnField,
  fieldReads,
  maxFieldThicknessNm,
  settingApplies,
  updateFieldUniforms,
} from '../../../src/fields/fields.ts';
import type { FieldSetting, SharedFieldSettings } from '../../../src/fields/thicknessField.ts';
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

/** Another valid value of a field's own setting than its default: the other state of a flag; halfway from a number's default to the farther end of its domain (whole for a whole number). */
const otherValue = (setting: FieldSetting): number | boolean => {
  if (setting.kind === 'flag') return !setting.defaultValue;
  const { min, max } = setting.domain;
  const far = max - setting.defaultValue >= setting.defaultValue - min ? max : min;
  const halfway = (setting.defaultValue + far) / 2;
  return setting.step === 'integer' ? Math.round(halfway) : halfway;
};

/** Another valid value of each setting a field may read than the default's (DEFAULT_SETTINGS). */
const OTHER_VALUE = {
  ...({ thicknessNm: 300, timeSeconds: 37 } satisfies SharedFieldSettings),
  ...Object.fromEntries(Object.entries<FieldSetting>(FIELD_SETTINGS).map(([key, setting]) => [key, otherValue(setting)])),
} as FieldSettings;

/** Points spread over the sphere (the golden angle in azimuth), from the bottom to the top. */
const SPHERE_POINTS = Array.from({ length: 400 }, (_, i) => {
  const y = -1 + (2 * i) / 399;
  const r = Math.sqrt(1 - y * y);
  const azimuth = 2.399963 * i;
  return [r * Math.cos(azimuth), y, r * Math.sin(azimuth)] as const;
});

/** Everything a field computes from the settings: its thickness over the sphere, what it derives, its maximum, its uniforms. */
function computed(name: FieldName, s: FieldSettings) {
  const field = THICKNESS_FIELDS[name];
  const uniforms = field.uniforms();
  const drawn = drawnField({ ...s, field: name });
  updateFieldUniforms(uniforms, { ...s, field: name }, drawn);
  return { thickness: SPHERE_POINTS.map((p) => field.thicknessAt(p, s)), derived: drawn.derived, max: drawn.maxThicknessNm, uniforms };
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
      const max = maxFieldThicknessNm({ ...s, field: name });
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
      const start = computed(name, DEFAULT_SETTINGS);
      const others = (Object.keys(OTHER_VALUE) as (keyof FieldSettings)[]).filter((key) => !settingApplies(key, name));
      for (const key of others) expect(computed(name, { ...DEFAULT_SETTINGS, [key]: OTHER_VALUE[key] }), key).toEqual(start);
    },
  );

  it('each setting a uniform, drained or swirling film reads changes its thickness somewhere', () => {
    const moving = { ...DEFAULT_SETTINGS, timeSeconds: 5 };
    for (const name of FIELDS.filter((f) => !THICKNESS_FIELDS[f].evolves)) {
      expect(fieldReads(name).length).toBeGreaterThan(0);
      for (const key of fieldReads(name))
        expect(computed(name, { ...moving, [key]: OTHER_VALUE[key] }).thickness, `${name} ${key}`).not.toEqual(
          computed(name, moving).thickness,
        );
    }
  });

  it('the flowing film reads its thickness, the time it is simulated to and every setting of its own, and none of the swirl', () => {
    expect([...fieldReads('flow')].sort()).toEqual(
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

  it("the flowing film's uniforms take the thickness and range the frame gives, not derived again of the settings", () => {
    const uniforms = THICKNESS_FIELDS.flow.uniforms();
    const drawn = drawnField({ ...DEFAULT_SETTINGS, field: 'flow' });
    const given = { derived: { ...drawn.derived!, thicknessNm: 321 }, maxThicknessNm: 1234 };
    updateFieldUniforms(uniforms, { ...DEFAULT_SETTINGS, field: 'flow' }, given);
    expect([uniforms.uThicknessNm!.value, uniforms.uFlowMaxThicknessNm!.value]).toEqual([321, 1234]);
  });
});

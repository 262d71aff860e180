import { type Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { bubbleDefines } from '../../../src/bubbleMaterials/bubbleMaterial.ts';
import {
  type EnvironmentSettings,
  createBackgroundMaterial,
  updateBackgroundMaterial,
} from '../../../src/bubbleMaterials/environmentMaterial.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';

const shown = (env: EnvironmentSettings['env']): EnvironmentSettings => ({ env, envRotationDeg: 0, exposure: 1 });

describe("a uniform coloured environment's material", () => {
  it('takes a new colour as a uniform value: the defines, and so the program, stay', () => {
    const m = createBackgroundMaterial();
    updateBackgroundMaterial(m, shown({ color: [1, 0.2, 0.2] }), null);
    const [defines, version] = [JSON.stringify(m.defines), m.version];
    updateBackgroundMaterial(m, shown({ color: [0, 4, 0.5] }), null);
    expect(JSON.stringify(m.defines)).toBe(defines);
    expect(m.version).toBe(version);
    expect((m.uniforms.uEnvironmentColor!.value as Vector3).toArray()).toEqual([0, 4, 0.5]);
    // Another kind is another program, and leaves no colour behind.
    updateBackgroundMaterial(m, shown('sky'), null);
    expect(JSON.stringify(m.defines)).not.toBe(defines);
    expect((m.uniforms.uEnvironmentColor!.value as Vector3).toArray()).toEqual([0, 0, 0]);
  });

  it("gives the bubble the same defines whatever the colour, and other defines than a name's", () => {
    const defines = (env: EnvironmentSettings['env']) => JSON.stringify(bubbleDefines({ ...DEFAULT_SETTINGS, env }, DEFAULT_FILM_QUALITY));
    expect(defines({ color: [0.5, 0.5, 0.5] })).toBe(defines({ color: [4, 0, 1] }));
    expect(defines({ color: [0.5, 0.5, 0.5] })).not.toBe(defines('none'));
  });
});

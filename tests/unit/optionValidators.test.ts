/**
 * One validator per option: the material's options and the colour tool's cases refuse the same
 * values with the same message (both call the option's one validator).
 */
import { describe, expect, it } from 'vitest';
import { spectralIridescenceOptions } from '../../src/meshMaterial/spectralIridescenceOptions.ts';
import { validateColorCase } from '../../src/cli/colorCase.ts';

const errorOf = (f: () => unknown): string => {
  try {
    f();
  } catch (e) {
    return (e as Error).message;
  }
  return 'accepted';
};

describe('one validator per option', () => {
  it.each([
    ['illuminant', { daylightCct: 6500, extra: 1 }],
    ['illuminant', { daylightCct: 3000 }],
    ['illuminant', 'D50'],
    ['polarization', 'circular'],
    ['normalization', 'peak'],
  ])('%s %j: the material and a cases file refuse it alike', (name, value) => {
    const material = errorOf(() => spectralIridescenceOptions({ [name]: value }));
    const cli = errorOf(() => validateColorCase({ [name]: value }, 0));
    expect(material).toMatch(new RegExp(`^${name}: .* is not allowed; expected `));
    expect(cli.endsWith(material.slice(name.length))).toBe(true);
  });
});

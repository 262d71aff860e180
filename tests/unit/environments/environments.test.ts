import { describe, expect, it } from 'vitest';
import {
  ENVIRONMENTS,
  ENVIRONMENT_EXPECTED,
  environmentColor,
  environmentKind,
  environmentText,
  isHdrEnvironment,
  readEnvironment,
} from '../../../src/environments/environments.ts';
import { ABSURDLY_LONG } from '../fixtures/badValues.ts';

/** What the messages say a colour may be, written out here rather than read from the module. */
const COLOR_EXPECTED = 'color:R,G,B, each in [0, 4]';

describe('an environment as text', () => {
  it('reads every registered name as itself', () => {
    for (const name of ENVIRONMENTS) expect(readEnvironment(name)).toEqual({ env: name });
  });

  it('reads color:R,G,B with each component in [0, 4], ends included, as a uniform colour, and writes it back', () => {
    for (const [text, color] of [
      ['color:1,0.2,0.2', [1, 0.2, 0.2]],
      ['color:0,0,0', [0, 0, 0]],
      ['color:4,4,4', [4, 4, 4]],
      ['color:0.5,.25,2.5e-1', [0.5, 0.25, 0.25]],
      ['color:+1,1,1', [1, 1, 1]],
    ] as const) {
      const reading = readEnvironment(text);
      expect(reading, text).toEqual({ env: { color } });
      const env = 'env' in reading ? reading.env : null;
      expect(readEnvironment(environmentText(env!)), text).toEqual(reading);
    }
    expect(environmentText({ color: [1, 0.2, 0.2] })).toBe('color:1,0.2,0.2');
  });

  it('refuses a component outside [0, 4], naming it and the end it passes', () => {
    for (const [text, problem] of [
      ['color:4.001,0,0', 'R is 4.001, above 4'],
      ['color:0,-0.001,0', 'G is -0.001, below 0'],
      ['color:1,1,1000', 'B is 1000, above 4'],
    ] as const)
      expect(readEnvironment(text), text).toEqual({ problem });
  });

  it('refuses a colour that is not three plain numbers', () => {
    for (const text of [
      'color:',
      'color:1',
      'color:1,1',
      'color:1,1,1,1',
      'color:1,,1',
      'color:a,b,c',
      'color:NaN,0,0',
      'color:Infinity,0,0',
      'color:0x1,0,0',
      'color: 1,1,1',
    ])
      expect(readEnvironment(text), text).toEqual({ problem: 'not three numbers R,G,B' });
  });

  it('refuses an unknown name, a colour not spelt color:, and nothing, with no more to say than what is expected', () => {
    for (const text of [
      '',
      'forest',
      'Sky',
      'sky ',
      'colour:1,1,1',
      'Color:1,1,1',
      '1,1,1',
      'rgb(1,1,1)',
      'constructor',
      '__proto__',
      ABSURDLY_LONG,
    ])
      expect(readEnvironment(text), text.slice(0, 40)).toEqual({ problem: null });
  });

  it('says what it expects: every name and the colour with its range', () => {
    expect(ENVIRONMENT_EXPECTED).toBe(`one of ${ENVIRONMENTS.join(', ')}, or ${COLOR_EXPECTED}`);
  });
});

describe("a uniform colour's kind", () => {
  it('is color, not HDR, and holds its colour; a name holds none', () => {
    const env = { color: [0.5, 0.5, 0.5] } as const;
    expect(environmentKind(env)).toBe('color');
    expect(isHdrEnvironment(env)).toBe(false);
    expect(environmentColor(env)).toEqual([0.5, 0.5, 0.5]);
    for (const name of ENVIRONMENTS) {
      expect(environmentColor(name), name).toBeNull();
      expect(environmentKind(name), name).not.toBe('color');
    }
  });
});

/** The fetches per fragment counted from GLSL text, on snippets whose count is known by reading them. */
import { describe, expect, it } from 'vitest';
import { loopNames, textureFetchesPerFragment } from '../../../scripts/docs/textureFetches.ts';

const shader = (...lines: string[]): string => ['uniform sampler2D uA;', ...lines].join('\n');

describe('textureFetchesPerFragment', () => {
  it('counts the calls of main and of the functions it calls, each as often as it is called', () => {
    const glsl = shader(
      'vec4 twice(ivec2 t) { return texelFetch(uA, t, 0) + texture(uA, vec2(t)); }',
      'void main() { gl_FragColor = twice(ivec2(0)) + twice(ivec2(1)) + texelFetch(uA, ivec2(2), 0); }',
    );
    expect(textureFetchesPerFragment(glsl, {})).toBe(5);
  });

  it('multiplies a constant loop by its passes, nested loops by both, a bound written <= by one more', () => {
    const glsl = shader(
      'void main() {',
      '  vec4 s = vec4(0.0);',
      '  for (int k = 0; k < 4; k++) s += texelFetch(uA, ivec2(k, 0), 0);',
      '  for (int i = 1; i <= 3; ++i) {',
      '    for (int j = 0; j < 2; j += 1) { s += texelFetch(uA, ivec2(i, j), 0); }',
      '    s += texelFetch(uA, ivec2(i, 9), 0);',
      '  }',
      '  gl_FragColor = s;',
      '}',
    );
    expect(textureFetchesPerFragment(glsl, {})).toBe(4 + 3 * (2 + 1));
  });

  it("takes a bound that is a define from the defines given and the shader's own, and a uniform's from the values", () => {
    const glsl = shader(
      '#define TAPS (2 * N_GIVEN + 1)',
      'uniform int uN;',
      'void main() {',
      '  int rows = 2 * uN;',
      '  vec4 s = vec4(0.0);',
      '  for (int k = 0; k < TAPS; k++) s += texelFetch(uA, ivec2(k, 0), 0);',
      '  for (int r = 0; r < rows; r++) s += texelFetch(uA, ivec2(r, 1), 0);',
      '  gl_FragColor = s;',
      '}',
    );
    expect(textureFetchesPerFragment(glsl, { N_GIVEN: 3 }, { values: { uN: 5 } })).toBe(7 + 10);
  });

  it('counts only the branches of #if the defines take, and both arms of a branch of code', () => {
    const glsl = shader(
      'void main() {',
      '#if MODE == 1',
      '  vec4 a = texelFetch(uA, ivec2(0), 0);',
      '#else',
      '  vec4 a = texelFetch(uA, ivec2(0), 0) + texelFetch(uA, ivec2(1), 0);',
      '#endif',
      '  gl_FragColor = a.x > 0.0 ? texelFetch(uA, ivec2(2), 0) : texelFetch(uA, ivec2(3), 0);',
      '}',
    );
    expect(textureFetchesPerFragment(glsl, { MODE: 1 })).toBe(3);
    expect(textureFetchesPerFragment(glsl, { MODE: 2 })).toBe(4);
  });

  it('counts a loop named to run once per call once, not once per pass of the loop around it', () => {
    const glsl = shader(
      'vec4 find(int m) {',
      '  for (int r = 0; r < 6; r++) {',
      '    if (texelFetch(uA, ivec2(r, 0), 0).r < 1.0) continue;',
      '    for (int i = 0; i < 4; i++) if (texelFetch(uA, ivec2(r, i), 0).r > 0.0) return vec4(1.0);',
      '  }',
      '  return vec4(0.0);',
      '}',
      'void main() { gl_FragColor = find(0) + find(1); }',
    );
    expect(textureFetchesPerFragment(glsl, {})).toBe(2 * 6 * (1 + 4));
    expect(textureFetchesPerFragment(glsl, {}, { oncePerCall: new Set(['find:i']) })).toBe(2 * (6 + 4));
    expect(loopNames(glsl, {})).toEqual(['find:r', 'find:i']);
  });

  it('is an error for a loop it cannot bound: a bound of no known value or of a variable, a while loop', () => {
    const unknown = shader('uniform int uN;', 'void main() { for (int k = 0; k < uN; k++) gl_FragColor = texelFetch(uA, ivec2(k), 0); }');
    expect(() => textureFetchesPerFragment(unknown, {})).toThrow(/uN/);
    const variable = shader('void main() { int n = 2; n += 1; for (int k = 0; k < n; k++) gl_FragColor = texelFetch(uA, ivec2(k), 0); }');
    expect(() => textureFetchesPerFragment(variable, {})).toThrow(/names n\b/);
    const whileLoop = shader('void main() { int k = 0; while (k < 3) { k++; } gl_FragColor = vec4(0.0); }');
    expect(() => textureFetchesPerFragment(whileLoop, {})).toThrow(/while/);
  });
});

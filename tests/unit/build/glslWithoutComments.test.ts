import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { glslWithoutComments } from '../../../scripts/build/glslWithoutComments.ts';

const shaderFiles = (dir: string): string[] =>
  readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? shaderFiles(join(dir, e.name)) : e.name.endsWith('.glsl') ? [join(dir, e.name)] : [],
  );

describe('glslWithoutComments', () => {
  it('drops line and block comments, indentation and blank lines, and keeps the code on its lines', () => {
    const glsl = [
      '// a file comment',
      '#ifndef GUARD // a guard',
      '#define GUARD',
      '',
      '/** A function:',
      ' *  two lines. */',
      'float f( float x ) {',
      '\treturn   x * /* inline */ 2.0; // doubled',
      '}',
      '#endif',
    ].join('\n');
    expect(glslWithoutComments(glsl)).toBe(
      ['#ifndef GUARD', '#define GUARD', 'float f( float x ) {', 'return x * 2.0;', '}', '#endif'].join('\n'),
    );
  });

  it('reads a comment opener inside the other kind of comment as part of that comment', () => {
    expect(glslWithoutComments('a; // b /* c\nd; /* e // f */ g;')).toBe('a;\nd; g;');
  });

  it("keeps every preprocessor directive of every shader, in order (a directive's line holds no comment start)", () => {
    for (const file of shaderFiles('shaders')) {
      const text = readFileSync(file, 'utf8');
      // Directives outside block comments, written on a line of their own; their text before any `//`.
      const directives = text
        .replace(/\/\*[\s\S]*?\*\//g, '')
        .split('\n')
        .map((l) => l.split('//')[0]!.trim().replace(/\s+/g, ' '))
        .filter((l) => l.startsWith('#'));
      const kept = glslWithoutComments(text)
        .split('\n')
        .filter((l) => l.startsWith('#'));
      expect(kept, file).toEqual(directives);
      expect(glslWithoutComments(text), file).not.toMatch(/\/\/|\/\*/);
    }
  });
});

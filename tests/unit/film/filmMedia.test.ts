/** The film's media: the uniforms TypeScript sets are exactly those the GLSL declares. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { filmMediaUniforms } from '../../../src/film/filmMedia.ts';

const declared = (file: string): string[] =>
  [...readFileSync(new URL(`../../../shaders/${file}`, import.meta.url), 'utf8').matchAll(/^uniform \w+ (\w+)/gm)].map((m) => m[1]!);

describe('film media uniforms', () => {
  it('filmMedia.ts sets what filmMedia.glsl and medium.glsl declare, no more and no less', () => {
    const glsl = [...declared('film/filmMedia.glsl'), ...declared('physics/medium.glsl')].sort();
    expect(Object.keys(filmMediaUniforms()).sort()).toEqual(glsl);
  });
});

/**
 * GLSL as the builds ship it: without comments, indentation or blank lines (the shaders are
 * written for reading; a user's bundle carries only what compiles). Line structure is kept, as
 * the preprocessor's directives need their own lines.
 */
import { readFile } from 'node:fs/promises';
import type { Plugin } from 'vite';

/**
 * `text` without its `//` and `/* … *\/` comments (a block comment that spans lines leaves its
 * line break, so directives around it stay on their own lines), each line trimmed with runs of
 * spaces and tabs made one space, and without empty lines. GLSL has no string literals, so every
 * `//` and `/*` opens a comment.
 */
export function glslWithoutComments(text: string): string {
  const code = text.replace(/\/\*[\s\S]*?\*\/|\/\/[^\n]*/g, (comment) => (comment.startsWith('/*') && comment.includes('\n') ? '\n' : ' '));
  return code
    .split('\n')
    .map((line) => line.replace(/[ \t]+/g, ' ').trim())
    .filter((line) => line !== '')
    .join('\n');
}

/** A Vite plugin: every `*.glsl?raw` import of a build is the file's text without comments. */
export const glslWithoutCommentsPlugin = (): Plugin => ({
  name: 'glsl-without-comments',
  apply: 'build',
  enforce: 'pre',
  async load(id) {
    if (!/\.glsl\?raw$/.test(id)) return null;
    return `export default ${JSON.stringify(glslWithoutComments(await readFile(id.slice(0, -'?raw'.length), 'utf8')))};`;
  },
});

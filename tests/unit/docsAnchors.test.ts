import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

/** GitHub's heading anchor: lower case, punctuation dropped, spaces to hyphens. */
const slug = (heading: string): string =>
  heading
    .trim()
    .toLowerCase()
    .replace(/[^\p{L}\p{N} -]/gu, '')
    .replace(/ /g, '-');

const files = (dir: string): string[] =>
  readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? files(path) : [path];
  });

describe('docs anchors cited in the code and docs exist', () => {
  const sources = ['src', 'shaders', 'tests', 'scripts'].flatMap(files).concat(['README.md'], files('docs'));
  const cited = new Set(
    sources.flatMap((f) =>
      [...readFileSync(f, 'utf8').matchAll(/(?:docs\/)?\b(physics|browser|gpu|flow)\.md#([\w-]+)/g)].map((m) => `${m[1]}.md#${m[2]}`),
    ),
  );
  it('cites some', () => expect(cited.size).toBeGreaterThan(0));
  for (const ref of cited) {
    it(ref, () => {
      const [file, anchor] = ref.split('#') as [string, string];
      const headings = readFileSync(join('docs', file), 'utf8')
        .split('\n')
        .filter((l) => /^#{1,6} /.test(l))
        .map((l) => slug(l.replace(/^#+ /, '')));
      expect(headings).toContain(anchor);
    });
  }
});

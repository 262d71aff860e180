/**
 * Every citation of a section of the docs, in the code, the scripts, the tests and the docs, leads
 * somewhere: a Markdown file's name with a section's anchor after '#' (a link, or a comment's
 * reference) names a file that exists and a heading of it; a link to an anchor alone, a heading of
 * its own page; and a README section named in prose (its title in quotes or italics after the
 * word README) is a heading of the README.
 */
import { existsSync, readFileSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
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

/** The anchors of a Markdown file's headings (fenced code left out: a `# comment` there is no heading). */
function anchorsOf(path: string): string[] {
  let fenced = false;
  return readFileSync(path, 'utf8')
    .split('\n')
    .filter((l) => {
      if (l.startsWith('```')) fenced = !fenced;
      return !fenced && /^#{1,6} /.test(l);
    })
    .map((l) => slug(l.replace(/^#+ /, '')));
}

/** The file a citation means: relative to the citing file, else to the repository, else in docs/. */
const resolve = (from: string, target: string): string | undefined =>
  [join(dirname(from), target), normalize(target), join('docs', target)].find((p) => existsSync(p) && statSync(p).isFile());

/** A text with comment continuations (` * `, `// `) joined, so a citation may run over a line break. */
const joined = (text: string): string => text.replace(/\n[ \t]*(?:\*(?!\/)|\/\/)?[ \t]*/g, ' ');

const sources = ['src', 'shaders', 'tests', 'scripts'].flatMap(files).concat(['README.md'], files('docs'));
const texts = new Map(sources.map((f) => [f, readFileSync(f, 'utf8')]));

/** Each cited section as `file#anchor` (the file as it resolves, or as written when it does not), with who cites it. */
const cited = new Map<string, string[]>();
const cite = (ref: string, by: string): void => void cited.set(ref, [...(cited.get(ref) ?? []), by]);
for (const [file, text] of texts) {
  for (const m of text.matchAll(/([\w./-]*\b[\w-]+\.md)#([\w-]+)/g)) cite(`${resolve(file, m[1]!) ?? m[1]!}#${m[2]!}`, file);
  if (file.endsWith('.md')) for (const m of text.matchAll(/\]\(#([\w-]+)\)/g)) cite(`${file}#${m[1]!}`, file);
  for (const m of joined(text).matchAll(/\bREADME(?:\.md)?(?:'s)?[,:]? ?\(?[*"“]([^*"”\n]{1,80})[*"”]/g)) {
    cite(`README.md#${slug(m[1]!)}`, file);
  }
}

describe('links to sections of the docs lead to a heading', () => {
  it('cites some', () => expect(cited.size).toBeGreaterThan(0));
  for (const [ref, by] of cited) {
    it(ref, () => {
      const [file, anchor] = ref.split('#') as [string, string];
      expect(existsSync(file), `${file} (cited by ${by.join(', ')}) does not exist`).toBe(true);
      const anchors = anchorsOf(file);
      expect(anchors.includes(anchor), `cited by ${by.join(', ')}; ${file}'s headings: ${anchors.join(', ')}`).toBe(true);
    });
  }
});

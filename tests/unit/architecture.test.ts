/**
 * The dependency direction of src/: every relative import points to the importer's own folder or
 * to a lower layer of SOURCE_LAYERS, never up or sideways; src/ imports neither tests/ nor
 * scripts/, and scripts/ never imports tests/.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { SOURCE_LAYERS } from '../../src/layers.ts';

const root = join(dirname(new URL(import.meta.url).pathname), '../..');
const sourceFiles = (dir: string): string[] =>
  readdirSync(join(root, dir), { recursive: true, encoding: 'utf8' })
    .filter((f) => f.endsWith('.ts'))
    .map((f) => join(dir, f));

/** Each relative import of `file` (a path from the repository root) as a path from the root. */
function importsOf(file: string): string[] {
  const text = readFileSync(join(root, file), 'utf8');
  const specifiers = [...text.matchAll(/(?:from|import)\s*\(?\s*'(\.{1,2}\/[^']+)'/g)].map((m) => m[1]!);
  return specifiers.map((s) => relative(root, join(root, dirname(file), s)));
}

const layerOf = (folder: string): number => SOURCE_LAYERS.findIndex((layer) => layer.includes(folder));
/** `src/film/filmTable.ts` → `film`; a file directly in src/ (this list) sits below every layer. */
const folderOf = (path: string): string => path.split('/')[1] ?? '';

describe('architecture', () => {
  const files = sourceFiles('src');

  it('every folder of src/ has a layer', () => {
    const folders = new Set(files.filter((f) => f.split('/').length > 2).map(folderOf));
    expect([...folders].filter((f) => layerOf(f) < 0)).toEqual([]);
  });

  it('src/ imports point to the same folder or a lower layer, never up or sideways', () => {
    const upward: string[] = [];
    for (const file of files) {
      const from = folderOf(file);
      for (const target of importsOf(file)) {
        if (!target.startsWith('src/')) {
          upward.push(`${file} → ${target}`);
          continue;
        }
        if (target.split('/').length === 2) continue; // src/layers.ts
        const to = folderOf(target);
        if (to !== from && layerOf(to) >= layerOf(from)) upward.push(`${file} → ${target}`);
      }
    }
    expect(files.length).toBeGreaterThan(50);
    expect(upward).toEqual([]);
  });

  it('scripts/ never imports tests/', () => {
    const intoTests = sourceFiles('scripts').flatMap((file) =>
      importsOf(file)
        .filter((t) => t.startsWith('tests/'))
        .map((t) => `${file} → ${t}`),
    );
    expect(intoTests).toEqual([]);
  });
});

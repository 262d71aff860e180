/**
 * The dependency direction of src/: every relative import points to the importer's own folder or
 * to a lower layer of SOURCE_LAYERS, never up or sideways; src/ imports neither tests/ nor
 * scripts/, and scripts/ never imports tests/. The maps of the layers (docs/architecture.md's
 * diagram and table, src/README.md's list) show SOURCE_LAYERS as it is.
 */
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { layerDiagramMermaid, layerListMarkdown } from '../../scripts/docs/layersMarkdown.ts';
import { withBlock } from '../../scripts/docs/withBlock.ts';
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

describe('the maps of the layers show SOURCE_LAYERS', () => {
  const architecture = readFileSync(join(root, 'docs/architecture.md'), 'utf8');
  const sourceReadme = readFileSync(join(root, 'src/README.md'), 'utf8');
  const block = (text: string, name: string): string => text.slice(text.indexOf(`<!-- ${name} -->`), text.indexOf(`<!-- /${name} -->`));

  it('every layer names folders of src/', () => {
    expect(SOURCE_LAYERS.flat().filter((f) => !existsSync(join(root, 'src', f)))).toEqual([]);
  });

  it('docs/architecture.md and src/README.md hold what npm run docs writes', () => {
    expect(withBlock(architecture, 'layer-diagram', layerDiagramMermaid())).toBe(architecture);
    expect(withBlock(sourceReadme, 'layer-list', layerListMarkdown())).toBe(sourceReadme);
  });

  it("the diagram boxes each layer's folders, and its arrows go from each layer to the one below", () => {
    const diagram = block(architecture, 'layer-diagram');
    const boxes = [...diagram.matchAll(/subgraph layer(\d+)\b([\s\S]*?)\n\s*end\n/g)].map((m) => ({
      layer: Number(m[1]),
      folders: [...m[2]!.matchAll(/src_(\w+)\["/g)].map((f) => f[1]!),
    }));
    expect(boxes.sort((a, b) => a.layer - b.layer).map((b) => b.folders)).toEqual(SOURCE_LAYERS);
    const chain = /^\s*(layer\d+(?: --> layer\d+)+)$/m.exec(diagram)![1]!.split(' --> ');
    expect(chain).toEqual(SOURCE_LAYERS.map((_, i) => `layer${SOURCE_LAYERS.length - 1 - i}`));
  });

  it("src/README.md lists each layer's folders, lowest first", () => {
    const listed = [...block(sourceReadme, 'layer-list').matchAll(/^(\d+)\. (.*)$/gm)].map((m) => ({
      layer: Number(m[1]),
      folders: [...m[2]!.matchAll(/\[`(\w+)\/`\]\(\1\/\)/g)].map((f) => f[1]!),
    }));
    expect(listed.map((l) => l.layer)).toEqual(SOURCE_LAYERS.map((_, i) => i));
    expect(listed.map((l) => l.folders)).toEqual(SOURCE_LAYERS);
  });

  it("docs/architecture.md's table names every folder once, lowest layer first", () => {
    const tableFolders = architecture
      .split('\n')
      .filter((l) => l.startsWith('| `src/'))
      .flatMap((l) => [...l.split(' | ')[0]!.matchAll(/`src\/(\w+)\/`/g)].map((m) => m[1]!));
    expect(tableFolders).toEqual(SOURCE_LAYERS.flat());
  });
});

/**
 * The layers of src/ as docs/architecture.md draws them and src/README.md lists them, generated
 * from SOURCE_LAYERS (the list the architecture test holds every import to), so neither can drift
 * from it. `npm run docs` writes both between their markers; a unit test checks they hold exactly this.
 */
import { readFileSync } from 'node:fs';
import { SOURCE_LAYERS } from '../../src/layers.ts';

/** A folder's node id: prefixed, so no folder name can be a mermaid keyword (`end`, `graph`). */
const nodeId = (folder: string): string => `src_${folder}`;
const layerId = (layer: number): string => `layer${layer}`;

/**
 * A mermaid flowchart, highest layer on top: one box per layer holding its folders, and an arrow
 * from each layer to the one below it, the way imports point.
 */
export function layerDiagramMermaid(): string {
  const top = SOURCE_LAYERS.length - 1;
  const boxes = SOURCE_LAYERS.map((folders, layer) => [
    `  subgraph ${layerId(layer)}["layer ${layer}"]`,
    '    direction LR',
    ...folders.map((folder) => `    ${nodeId(folder)}["${folder}/"]`),
    '  end',
  ])
    .reverse()
    .flat();
  const arrows = SOURCE_LAYERS.map((_, layer) => layerId(top - layer)).join(' --> ');
  return ['```mermaid', 'flowchart TB', ...boxes, `  ${arrows}`, '```'].join('\n');
}

/**
 * What each layer holds, in the words of its line's comment in src/layers.ts
 * (`['film', 'flow'], // the film's colour …`); an error if those lines do not give SOURCE_LAYERS.
 */
function layerComments(): string[] {
  const text = readFileSync(new URL('../../src/layers.ts', import.meta.url), 'utf8');
  const lines = [...text.matchAll(/^ {2}\[([^\]]*)\], \/\/ (.+)$/gm)];
  const folders = lines.map((m) => [...m[1]!.matchAll(/'([^']+)'/g)].map((f) => f[1]!));
  if (JSON.stringify(folders) !== JSON.stringify(SOURCE_LAYERS)) {
    throw new Error("src/layers.ts: write each layer on one line as ['folder', …], // what it holds");
  }
  return lines.map((m) => m[2]!);
}

/** A Markdown list of the layers, lowest first: each layer's number, its folders (linked) and what it holds. */
export function layerListMarkdown(): string {
  const comments = layerComments();
  return SOURCE_LAYERS.map(
    (folders, layer) => `${layer}. ${folders.map((f) => `[\`${f}/\`](${f}/)`).join(' · ')} — ${comments[layer]}`,
  ).join('\n');
}

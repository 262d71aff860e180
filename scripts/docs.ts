/**
 * `npm run docs`: writes the generated blocks of the docs: the README's URL parameters (from the
 * schema), and the layers of src/ in docs/architecture.md and src/README.md (from SOURCE_LAYERS).
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { layerDiagramMermaid, layerListMarkdown } from './docs/layersMarkdown.ts';
import { urlTableMarkdown } from './docs/urlTable.ts';
import { withBlock } from './docs/withBlock.ts';

const writeBlock = (path: string, name: string, content: string): void => {
  const file = new URL(`../${path}`, import.meta.url);
  writeFileSync(file, withBlock(readFileSync(file, 'utf8'), name, content));
};

writeBlock('README.md', 'url-table', urlTableMarkdown());
writeBlock('docs/architecture.md', 'layer-diagram', layerDiagramMermaid());
writeBlock('src/README.md', 'layer-list', layerListMarkdown());

/**
 * `npm run docs`: writes the generated blocks of the docs: the README's URL parameters (from the
 * schema), the layers of src/ in docs/architecture.md and src/README.md (from SOURCE_LAYERS), and
 * the flowing film's cost in docs/flow.md (from its passes, counted as the app draws them). The
 * cost's module reads the shaders through Vite's `import.meta.glob`, so it runs in Vite's module runner.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { runnerImport } from 'vite';
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
const flowCost = await runnerImport<typeof import('./docs/flowCost.ts')>(new URL('./docs/flowCost.ts', import.meta.url).pathname, {
  configFile: false,
  logLevel: 'error',
});
writeBlock('docs/flow.md', 'flow-cost', flowCost.module.flowCostMarkdown());

/** `npm run docs`: writes the README's generated table (the URL parameters, from the schema). */
import { readFileSync, writeFileSync } from 'node:fs';
import { urlTableMarkdown, withBlock } from './docs/urlTable.ts';

const README = new URL('../README.md', import.meta.url);
writeFileSync(README, withBlock(readFileSync(README, 'utf8'), 'url-table', urlTableMarkdown()));

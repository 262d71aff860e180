/** The README is a short front door, and its URL table is the schema's. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { urlTableMarkdown } from '../../scripts/docs/urlTable.ts';
import { withBlock } from '../../scripts/docs/withBlock.ts';
import { VIEW_PARAMETERS } from '../../src/settings/viewParameters.ts';

const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8');

describe('README', () => {
  it('holds the URL table generated from the schema (npm run docs writes it)', () => {
    expect(withBlock(readme, 'url-table', urlTableMarkdown())).toBe(readme);
  });

  it('names every parameter of the schema in its table, once', () => {
    const block = readme.slice(readme.indexOf('<!-- url-table -->'), readme.indexOf('<!-- /url-table -->'));
    for (const row of VIEW_PARAMETERS) expect(block.split(`| \`${row.url}\` |`).length, row.url).toBe(2);
  });

  it('is at most 250 lines and starts with the two commands, as .ci/run runs the second', () => {
    expect(readme.split('\n').length).toBeLessThanOrEqual(250);
    const firstBlock = /```sh\n([\s\S]*?)```/.exec(readme)![1]!;
    expect(firstBlock).toMatch(/^npm install && npm run dev\b/m);
    expect(firstBlock).toMatch(/^npm install && npm test\b/m);
    expect(readFileSync(new URL('../../.ci/run', import.meta.url), 'utf8')).toMatch(/^npm ci && npm test$/m);
  });
});

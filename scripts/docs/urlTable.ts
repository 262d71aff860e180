/**
 * The README's table of the demo's URL parameters and the demo's defaults, generated from the schema (VIEW_PARAMETERS:
 * the same rows the URL parser, the element's attributes, the panel and the usage texts come
 * from), so the table cannot drift from what the page accepts. `npm run docs` writes it between
 * the README's markers; a unit test checks the README holds exactly this.
 */
import { VIEW_PARAMETERS } from '../../src/settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../../src/settings/demoView.ts';

const cell = (text: string): string => text.replaceAll('|', '\\|');

export function urlTableMarkdown(): string {
  // The demo's default (demoView.ts): what its URL leaves out.
  const rows = VIEW_PARAMETERS.map((r) => [r, r.write(DEMO_VIEW_SETTINGS)] as const).map(
    ([r, d]) => `| \`${r.url}\` | ${cell(r.label)} | ${cell(r.expected)} | ${d === '' ? 'none' : `\`${cell(d)}\``} |`,
  );
  return ['| parameter | what it sets | accepts | default |', '|---|---|---|---|', ...rows].join('\n');
}

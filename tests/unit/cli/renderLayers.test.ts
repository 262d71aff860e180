/** The render command takes the schema's `layers` as every URL parameter: `--layers TEXT`, or a string in a cases file. */
import { describe, expect, it } from 'vitest';
import { parseRenderCases, parseRenderCommandLine } from '../../../src/cli/renderOptions.ts';
import { parseSettings } from '../../../src/settings/settingsQuery.ts';

describe('render --layers', () => {
  it('puts the stack into the view query, read back as the URL reads it', () => {
    const command = parseRenderCommandLine(['--layers', '1.38:d/(TiO2:50/SiO2:90)*3', '--out', 'a.png']);
    expect(command.kind).toBe('views');
    const [view] = (command as Extract<typeof command, { kind: 'views' }>).views;
    const { settings, errors } = parseSettings(`?${view!.query}`);
    expect(errors).toEqual([]);
    expect(settings.layers).toHaveLength(7);
    expect(settings.layers[0]).toEqual({ n: 1.38, thicknessNm: 'd' });
  });

  it('refuses a bad stack, naming --layers (or the case field) and the rule', () => {
    expect(() => parseRenderCommandLine(['--layers', '(1.5:1)*0', '--out', 'a.png'])).toThrow(/^--layers: .*not an integer in \[1, 64\]/);
    expect(() => parseRenderCases('[{ "out": "b.png", "layers": "1.5:1//1.6:1" }]', 'views.json', new Map())).toThrow(
      /^case at index 0: layers: .*an empty entry/,
    );
    const [view] = parseRenderCases('[{ "out": "c.png", "layers": "(2.35:56.6/1.46:91.1)*8" }]', 'views.json', new Map());
    expect(parseSettings(`?${view!.query}`).settings.layers).toHaveLength(16);
  });
});

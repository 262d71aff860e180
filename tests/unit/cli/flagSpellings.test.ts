/**
 * One spelling for the command line: the colour, film and render tools spell every flag as the
 * settings schema's URL name in kebab case, and refuse the other spellings naming the flag.
 */
import { describe, expect, it } from 'vitest';
import { USAGE } from '../../../src/cli/usage.ts';
import { FILM_USAGE } from '../../../src/cli/runFilmCommand.ts';
import { RENDER_USAGE } from '../../../src/cli/renderUsage.ts';
import { runColorCommand } from '../../../src/cli/runColorCommand.ts';

const flagsIn = (usage: string): Set<string> => new Set([...usage.matchAll(/(?<![\w-])--[A-Za-z][\w-]*/g)].map((m) => m[0]));
const TOOLS = { color: USAGE, film: FILM_USAGE, render: RENDER_USAGE };

describe('flag spellings', () => {
  it('every flag of every tool is lower-case words joined by hyphens', () => {
    for (const [tool, usage] of Object.entries(TOOLS)) {
      for (const flag of flagsIn(usage)) expect(flag, tool).toMatch(/^--[a-z0-9]+(-[a-z0-9]+)*$/);
    }
  });

  it('the thickness is --thickness in all three tools; the film index --n-film in colour and render', () => {
    for (const usage of Object.values(TOOLS)) expect(flagsIn(usage)).toContain('--thickness');
    expect(flagsIn(RENDER_USAGE)).toContain('--thickness-range');
    for (const usage of [USAGE, RENDER_USAGE]) expect(flagsIn(usage)).toContain('--n-film');
    for (const usage of Object.values(TOOLS))
      for (const old of ['--thickness-nm', '--radius-mm']) expect(flagsIn(usage)).not.toContain(old);
  });

  it("the colour tool refuses the URL's camel case naming the flag (exit 2)", () => {
    const r = runColorCommand(['--nFilm', '1.4'], () => '');
    expect(r).toMatchObject({ exitCode: 2, stdout: '' });
    expect(r.stderr).toBe('color: --nFilm: unknown flag; it is spelt --n-film\n');
  });
});

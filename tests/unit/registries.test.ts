/**
 * Every kind that grows (evaluation methods, thickness fields, environments, named media) is
 * registered in one place, and code elsewhere asks the registry what a member does instead of
 * comparing its name: no `s.mode === 'table'`, no `switch (s.env)` outside the kind's own files.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { ENVIRONMENTS } from '../../src/environments/environments.ts';
import { FIELDS } from '../../src/fields/fields.ts';
import { FILM_METHODS } from '../../src/methods/methods.ts';
import { MEDIUM_NAMES } from '../../src/physics/namedMedia.ts';

const root = join(dirname(new URL(import.meta.url).pathname), '../..');

/** A kind: its members' names, the settings keys that hold one, and the files that may compare names (its registry and members). */
interface Kind {
  readonly names: readonly string[];
  readonly keys: readonly string[];
  readonly home: readonly string[];
}

const KINDS: Readonly<Record<string, Kind>> = {
  method: { names: FILM_METHODS, keys: ['mode', 'method'], home: ['src/methods/'] },
  field: { names: FIELDS, keys: ['field'], home: ['src/fields/'] },
  environment: { names: ENVIRONMENTS, keys: ['env', 'environment'], home: ['src/environments/'] },
  medium: {
    names: MEDIUM_NAMES,
    keys: ['nFilm', 'nInside', 'nOutside', 'film', 'base', 'medium'],
    home: ['src/physics/namedMedia.ts'],
  },
};

/** The last name of an expression (`this.settings.mode` → `mode`, `s?.env` → `env`). */
const lastName = (expression: string): string => /(\w+)\W*$/.exec(expression)?.[1] ?? '';

/** Each place in `text` that picks by a kind's member name: a comparison with one, or a switch on the kind's key. */
function namePicks(text: string, kind: Kind): string[] {
  const found: string[] = [];
  const literal = `(?<q>['"\`])(?<name>[\\w-]+)\\k<q>`;
  const operand = '(?<expr>[\\w$.?!\\]\\[]+)';
  for (const pattern of [new RegExp(`${operand}\\s*[!=]==?\\s*${literal}`, 'g'), new RegExp(`${literal}\\s*[!=]==?\\s*${operand}`, 'g')])
    for (const m of text.matchAll(pattern))
      if (kind.keys.includes(lastName(m.groups!.expr!)) && kind.names.includes(m.groups!.name!)) found.push(m[0]);
  for (const m of text.matchAll(/switch\s*\(([^)]*)\)/g)) if (kind.keys.includes(lastName(m[1]!))) found.push(m[0]);
  return found;
}

const sourceFiles = readdirSync(join(root, 'src'), { recursive: true, encoding: 'utf8' })
  .filter((f) => f.endsWith('.ts'))
  .map((f) => `src/${f}`);

describe('registries', () => {
  for (const [name, kind] of Object.entries(KINDS))
    it(`no code outside the ${name} registry picks a ${name} by its name`, () => {
      const picks: string[] = [];
      for (const file of sourceFiles) {
        if (kind.home.some((home) => file.startsWith(home))) continue;
        for (const pick of namePicks(readFileSync(join(root, file), 'utf8'), kind)) picks.push(`${file}: ${pick}`);
      }
      expect(kind.names.length).toBeGreaterThan(1);
      expect(picks).toEqual([]);
    });

  it('the check finds a comparison of either order, a switch, and not a comparison of another key', () => {
    const method = KINDS.method!;
    expect(namePicks("if (s.mode === 'table') draw();", method)).toHaveLength(1);
    expect(namePicks("const x = 'fourier' !== this.settings.mode;", method)).toHaveLength(1);
    expect(namePicks('switch (view.current.mode) {}', method)).toHaveLength(1);
    expect(namePicks("if (flags.kind === 'table') print();", method)).toEqual([]);
    expect(namePicks("s.field === 'swirl'", KINDS.field!)).toHaveLength(1);
    expect(namePicks("nInside === 'Au'", KINDS.medium!)).toHaveLength(1);
  });
});

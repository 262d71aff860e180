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

/**
 * A kind: its members' names, the settings keys that hold one, the files that may compare names (its
 * registry and members), and the folders scanned (absent: the source only).
 */
interface Kind {
  readonly names: readonly string[];
  readonly keys: readonly string[];
  readonly home: readonly string[];
  readonly scanned?: readonly string[];
}

const KINDS: Readonly<Record<string, Kind>> = {
  // The registry reaches each method's facts and its float64 twin, so the bench and the tests look methods up too.
  method: { names: FILM_METHODS, keys: ['mode', 'method'], home: ['src/methods/'], scanned: ['src', 'scripts', 'tests'] },
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

/** The code that may be scanned: the source, the scripts and the tests, this file (which holds the patterns as examples) aside. */
const SCANNED = ['src', 'scripts', 'tests'];
const THIS_FILE = 'tests/unit/registries.test.ts';
const codeFiles = SCANNED.flatMap((folder) =>
  readdirSync(join(root, folder), { recursive: true, encoding: 'utf8' })
    .filter((f) => f.endsWith('.ts'))
    .map((f) => `${folder}/${f}`),
).filter((f) => f !== THIS_FILE);

describe('registries', () => {
  for (const [name, kind] of Object.entries(KINDS))
    it(`no code outside the ${name} registry picks a ${name} by its name`, () => {
      const picks: string[] = [];
      for (const file of codeFiles) {
        if (!(kind.scanned ?? ['src']).some((folder) => file.startsWith(`${folder}/`))) continue;
        if (kind.home.some((home) => file.startsWith(home))) continue;
        for (const pick of namePicks(readFileSync(join(root, file), 'utf8'), kind)) picks.push(`${file}: ${pick}`);
      }
      expect(kind.names.length).toBeGreaterThan(1);
      expect(picks).toEqual([]);
    });

  it('the methods are looked for in the scripts and the tests as well as the source', () => {
    for (const folder of SCANNED)
      expect(
        codeFiles.some((f) => f.startsWith(`${folder}/`)),
        folder,
      ).toBe(true);
    expect(codeFiles).toContain('scripts/bench/progress.ts');
    expect(codeFiles).toContain('tests/e2e/parity.spec.ts');
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

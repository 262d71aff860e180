/**
 * Every kind that grows (evaluation methods, thickness fields, environments, named media) is
 * registered in one place, and code elsewhere (the source, the scripts and the tests) asks the
 * registry what a member does instead of comparing its name: no `s.mode === 'table'`, no
 * `switch (s.env)`, no `['flow', 'swirl'].includes(field)` outside the kind's own files.
 *
 * The rule: a pick is a branch on which member a value is. An expression holds a member of a kind
 * when its last name is one of the kind's keys (`this.settings.mode`, `c.env`, `row.settings.field`,
 * `nInside`), and the branches are
 * - a comparison (`===`, `!==`, `==`, `!=`, either order, a ternary's test included) of such an
 *   expression with a string naming a member;
 * - a `switch` on such an expression (its `case` labels are the names);
 * - a search (`includes`, `indexOf`, `has`) for such an expression in a list holding a member's
 *   name: a list written there, or one the file declares (`const X = [...]`, `new Set([...])`).
 * Choosing a member is not a pick: a name as a value (`{ env: 'park' }`, `?env=park`,
 * `mode: 'fourier'`), a list of the members a test runs through, a test about one member by name.
 * A comparison of a key that holds something else under a member's name (`command.kind === 'table'`,
 * `folder === 'flow'`, an environment's kind `'none'`) is not one either: its last name is not the kind's.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { ENVIRONMENTS } from '../../src/environments/environments.ts';
import { FIELDS } from '../../src/fields/fields.ts';
import { FILM_METHODS } from '../../src/methods/methods.ts';
import { MEDIUM_NAMES } from '../../src/physics/namedMedia.ts';

const root = join(dirname(new URL(import.meta.url).pathname), '../..');

/** A kind: its members' names, the keys of the expressions that hold one, and the files that may compare names (its registry and members). */
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

/** The last name of an expression (`this.settings.mode` → `mode`, `s?.env` → `env`, `c.env!` → `env`). */
const lastName = (expression: string): string => /(\w+)\W*$/.exec(expression)?.[1] ?? '';

const LITERAL = /(['"`])([\w-]+)\1/g;
/** Whether a list's text (`['flow', 'swirl']`) names a member of `kind`. */
const namesMember = (list: string, kind: Kind): boolean => [...list.matchAll(LITERAL)].some((m) => kind.names.includes(m[2]!));

/** Each place in `text` that picks by a kind's member name (the rule above). */
function namePicks(text: string, kind: Kind): string[] {
  const found: string[] = [];
  const holds = (expression: string) => kind.keys.includes(lastName(expression));
  const literal = `(?<q>['"\`])(?<name>[\\w-]+)\\k<q>`;
  const operand = '(?<expr>[\\w$.?!\\]\\[]+)';
  for (const pattern of [new RegExp(`${operand}\\s*[!=]==?\\s*${literal}`, 'g'), new RegExp(`${literal}\\s*[!=]==?\\s*${operand}`, 'g')])
    for (const m of text.matchAll(pattern)) if (holds(m.groups!.expr!) && kind.names.includes(m.groups!.name!)) found.push(m[0]);
  for (const m of text.matchAll(/switch\s*\(([^)]*)\)/g)) if (holds(m[1]!)) found.push(m[0]);
  // The lists the file declares, by their name.
  const declared = new Map<string, string>();
  for (const m of text.matchAll(/(?:const|let)\s+(\w+)\b[^=;]*=\s*(?:new Set(?:<[^>]*>)?\(\s*)?(\[[^\][]*\])/g)) declared.set(m[1]!, m[2]!);
  const search = /(?<list>\[[^\][]*\]|\b\w+)(?:\s+as\s+[^()]*?)?\)?\s*\.(?:includes|indexOf|has)\(\s*(?<expr>[\w$.?!\][]+)\s*[,)]/g;
  for (const m of text.matchAll(search)) {
    const list = m.groups!.list!.startsWith('[') ? m.groups!.list! : (declared.get(m.groups!.list!) ?? '');
    if (holds(m.groups!.expr!) && namesMember(list, kind)) found.push(m[0]);
  }
  return found;
}

/** The code scanned: the source, the scripts and the tests, this file (which holds the patterns as examples) aside. */
const SCANNED = ['src', 'scripts', 'tests'] as const;
/** Fewer files than these in a folder: the scan missed it (a wrong path or filter), not a smaller tree. */
const LEAST_FILES: Readonly<Record<(typeof SCANNED)[number], number>> = { src: 150, scripts: 30, tests: 100 };
const THIS_FILE = 'tests/unit/registries.test.ts';
const codeFiles = SCANNED.flatMap((folder) =>
  readdirSync(join(root, folder), { recursive: true, encoding: 'utf8' })
    .filter((f) => f.endsWith('.ts'))
    .map((f) => `${folder}/${f}`),
).filter((f) => f !== THIS_FILE);
const texts = new Map(codeFiles.map((f) => [f, readFileSync(join(root, f), 'utf8')]));

/** The picks of `kind` in a file's text: none in the kind's own files. */
const picksIn = (file: string, text: string, kind: Kind): string[] =>
  kind.home.some((home) => file.startsWith(home)) ? [] : namePicks(text, kind).map((pick) => `${file}: ${pick}`);

describe('registries', () => {
  for (const [name, kind] of Object.entries(KINDS))
    it(`no code outside the ${name} registry picks a ${name} by its name`, () => {
      expect(kind.names.length).toBeGreaterThan(1);
      expect(codeFiles.flatMap((file) => picksIn(file, texts.get(file)!, kind))).toEqual([]);
    });

  it('the source, the scripts and the tests are all scanned', () => {
    for (const folder of SCANNED)
      expect(codeFiles.filter((f) => f.startsWith(`${folder}/`)).length, folder).toBeGreaterThanOrEqual(LEAST_FILES[folder]);
    expect(codeFiles).toContain('scripts/bench/progress.ts');
    expect(codeFiles).toContain('tests/e2e/parity.spec.ts');
  });

  it("a pick added to a scanned file of each folder, outside the kind's home, is found", () => {
    for (const kind of Object.values(KINDS))
      for (const folder of SCANNED) {
        const file = codeFiles.find((f) => f.startsWith(`${folder}/`) && !kind.home.some((home) => f.startsWith(home)))!;
        const text = texts.get(file)!;
        const added = `${text}\nif (s.${kind.keys[0]} === '${kind.names[1]}') draw();\n`;
        expect(picksIn(file, added, kind).length, `${file}, ${kind.keys[0]}`).toBe(picksIn(file, text, kind).length + 1);
      }
  });

  it('the check finds a comparison of either order, a ternary, a switch and a search of a list of names', () => {
    const { method, field, environment, medium } = KINDS as Record<string, Kind>;
    expect(namePicks("if (s.mode === 'table') draw();", method!)).toHaveLength(1);
    expect(namePicks("const x = 'fourier' !== this.settings.mode;", method!)).toHaveLength(1);
    expect(namePicks("const e = c.env === 'sky' ? { kind: 'sky' } : map;", environment!)).toHaveLength(1);
    expect(namePicks('switch (view.current.mode) {}', method!)).toHaveLength(1);
    expect(namePicks("s.field === 'swirl'", field!)).toHaveLength(1);
    expect(namePicks("nInside === 'Au'", medium!)).toHaveLength(1);
    expect(namePicks("if (['flow', 'swirl'].includes(s.field)) step();", field!)).toHaveLength(1);
    expect(namePicks("(['park', 'city'] as readonly string[]).includes(env)", environment!)).toHaveLength(1);
    expect(namePicks("new Set(['Au', 'Ag']).has(nInside)", medium!)).toHaveLength(1);
    expect(namePicks("const SLOW = ['exact'] as const;\nif (SLOW.indexOf(row.mode) >= 0) wait();", method!)).toHaveLength(1);
    expect(namePicks("const METALS = new Set<string>(['Au', 'Cu']);\nMETALS.has(s.nInside)", medium!)).toHaveLength(1);
  });

  it('the check passes choosing a member, and the same names held by other keys', () => {
    const { method, field, environment } = KINDS as Record<string, Kind>;
    for (const text of [
      "await showSettings(page, { env: 'park', envRotationDeg: 0 });",
      'await page.goto(`/?env=park&envRotation=120`);',
      "for (const env of ['park', 'sky']) open(env);",
      "const CASES: { env: 'sky' | HdrEnvironment }[] = [{ env: 'sky' }];",
      "if (environmentKind(s.env) !== 'none') light();",
      'if (SKIES.includes(env)) draw();',
    ])
      expect(namePicks(text, environment!), text).toEqual([]);
    expect(namePicks("if (flags.kind === 'table') print();", method!)).toEqual([]);
    expect(namePicks("drawnMethod({ ...FILM, mode: 'fourier' }).mode === shown", method!)).toEqual([]);
    expect(namePicks("['table', 'fourier'].includes(format)", method!)).toEqual([]);
    expect(namePicks("['bins', 'series'].includes(s.mode)", method!)).toEqual([]);
    expect(namePicks("r.control?.folder === 'flow'", field!)).toEqual([]);
  });
});

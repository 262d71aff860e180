import { parseArgs } from 'node:util';
import { ParameterError, describeValue, rejectValue } from '../input/validate.ts';
import { VIEW_PARAMETERS } from '../settings/viewParameters.ts';

export interface Flags {
  /** Each value flag given, by name (without "--"); a flag with nothing after it reads as ''. */
  readonly values: Map<string, string>;
  /** The switches (flags without a value) given. */
  readonly switches: Set<string>;
}

/** What a tool takes: its value flags and switches, and other spellings it refuses naming the flag (spelling → flag). */
export interface FlagSpec {
  readonly values: readonly string[];
  readonly switches: readonly string[];
  readonly spellings?: ReadonlyMap<string, string>;
}

/**
 * The URL's spellings of the schema's flags among `flags` where the two differ (`nFilm` for
 * `n-film`): a tool's flag is the URL name in kebab case, and the URL's own spelling is refused naming it.
 */
export const urlSpellings = (flags: readonly string[]): Map<string, string> =>
  new Map(VIEW_PARAMETERS.filter((row) => row.url !== row.flag && flags.includes(row.flag)).map((row) => [row.url, row.flag]));

/**
 * The flags of a command line: `--name value` for each value flag, bare `--name` for each switch,
 * each at most once, nothing else (no positional arguments, no unknown flags; another spelling of a
 * flag is refused naming the flag). A ParameterError names the first offender.
 */
export function readFlags(argv: readonly string[], spec: FlagSpec): Flags {
  const { values: valueFlags, switches } = spec;
  const options = Object.fromEntries<{ type: 'string' | 'boolean' }>([
    ...valueFlags.map((f): [string, { type: 'string' }] => [f, { type: 'string' }]),
    ...switches.map((f): [string, { type: 'boolean' }] => [f, { type: 'boolean' }]),
  ]);
  const { tokens } = parseArgs({ args: [...argv], options, strict: false, allowPositionals: true, tokens: true });
  const values = new Map<string, string>();
  const given = new Set<string>();
  for (const token of tokens) {
    if (token.kind !== 'option') {
      rejectValue('argument', token.kind === 'positional' ? token.value : '--', 'only flags, each --name value (see --help)');
    }
    const flag = `--${token.name}`;
    if (switches.includes(token.name)) {
      if (token.value !== undefined) rejectValue(flag, token.value, 'no value');
      given.add(token.name);
      continue;
    }
    if (!valueFlags.includes(token.name)) unknownFlag(token.rawName, token.name, spec);
    if (values.has(token.name)) throw new ParameterError(flag, `${flag}: given more than once; expected it at most once`);
    // A flag with nothing after it reads as an empty value, which every number check rejects; an
    // absurdly long value is refused by the same checks, its message naming the allowed range.
    values.set(token.name, token.value ?? '');
  }
  return { values, switches: given };
}

/** The refusal of a flag the tool does not take: the flag it is another spelling of, else every flag the tool takes. */
function unknownFlag(rawName: string, name: string, spec: FlagSpec): never {
  const spelt = spec.spellings?.get(name);
  if (spelt !== undefined) throw new ParameterError(rawName, `${rawName}: unknown flag; it is spelt --${spelt}`);
  const all = [...spec.values, ...spec.switches].map((f) => `--${f}`).join(', ');
  throw new ParameterError(rawName, `${describeValue(rawName)}: unknown flag; expected one of ${all}`);
}

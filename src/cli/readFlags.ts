import { parseArgs } from 'node:util';
import { ParameterError, describeValue, rejectValue } from '../input/validate.ts';

export interface Flags {
  /** Each value flag given, by name (without "--"); a flag with nothing after it reads as ''. */
  readonly values: Map<string, string>;
  /** The switches (flags without a value) given. */
  readonly switches: Set<string>;
}

/**
 * The flags of a command line: `--name value` for each of `valueFlags`, bare `--name` for each of
 * `switches`, each at most once, nothing else (no positional arguments, no unknown flags). A
 * ParameterError names the first offender.
 */
export function readFlags(argv: readonly string[], valueFlags: readonly string[], switches: readonly string[]): Flags {
  const options = Object.fromEntries<{ type: 'string' | 'boolean' }>([
    ...valueFlags.map((f): [string, { type: 'string' }] => [f, { type: 'string' }]),
    ...switches.map((f): [string, { type: 'boolean' }] => [f, { type: 'boolean' }]),
  ]);
  const allFlags = [...valueFlags, ...switches].map((f) => `--${f}`).join(', ');
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
    if (!valueFlags.includes(token.name)) {
      throw new ParameterError(token.rawName, `${describeValue(token.rawName)}: unknown flag; expected one of ${allFlags}`);
    }
    if (values.has(token.name)) throw new ParameterError(flag, `${flag}: given more than once; expected it at most once`);
    // A flag with nothing after it reads as an empty value, which every number check rejects; an
    // absurdly long value is refused by the same checks, its message naming the allowed range.
    values.set(token.name, token.value ?? '');
  }
  return { values, switches: given };
}

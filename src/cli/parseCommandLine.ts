import { parseArgs } from 'node:util';
import { GAMUT_MAPPINGS, type GamutMapping } from '../physics/colorConversions.ts';
import { NAMED_ILLUMINANTS } from '../physics/illuminants.ts';
import { ParameterError, expectedNumber, isInDomain } from '../physics/validate.ts';
import {
  type CaseField,
  type ColorCase,
  DAYLIGHT_CCT_DOMAIN_K,
  ILLUMINANT_EXPECTED,
  NUMBER_FIELDS,
  type NumberField,
  WAVELENGTH_DOMAIN_NM,
  validateColorCase,
} from './colorCase.ts';
import { describeValue, oneOf, rejectValue } from './inputErrors.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';
import { parseColonRange, parseRange } from './tableValues.ts';

/** The flags that set one field of the case (or of every row of a table). */
const FLAG_FIELDS = {
  thickness: 'thicknessNm',
  angle: 'angleDeg',
  'n-outside': 'nOutside',
  'n-film': 'nFilm',
  'n-inside': 'nInside',
  illuminant: 'illuminant',
  polarization: 'polarization',
  normalization: 'normalization',
  wavelengths: 'wavelengthsNm',
} as const satisfies Record<string, Exclude<CaseField, 'id'>>;
type CaseFlag = keyof typeof FLAG_FIELDS;
const MODE_FLAGS = ['cases', 'from', 'to', 'step', 'angles', 'format', 'gamut'] as const;
type Flag = CaseFlag | (typeof MODE_FLAGS)[number];
const VALUE_FLAGS = [...(Object.keys(FLAG_FIELDS) as CaseFlag[]), ...MODE_FLAGS];
const ALL_FLAGS = [...VALUE_FLAGS, 'help'].map((f) => `--${f}`).join(', ');

export const OUTPUT_FORMATS = ['json', 'csv'] as const;
export type OutputFormat = (typeof OUTPUT_FORMATS)[number];

export type Command =
  | { readonly kind: 'help' }
  | { readonly kind: 'cases'; readonly cases: readonly ColorCase[]; readonly gamut: GamutMapping }
  | { readonly kind: 'casesFile'; readonly path: string; readonly gamut: GamutMapping }
  | {
      readonly kind: 'table';
      readonly variable: 'thicknessNm' | 'angleDeg';
      readonly values: readonly number[];
      readonly base: ColorCase;
      readonly gamut: GamutMapping;
      readonly format: OutputFormat;
    };

/**
 * What the command line asks for, every value checked; a ParameterError for the first bad one.
 * Pure: the cases file is named here and read by the caller.
 */
export function parseCommandLine(argv: readonly string[]): Command {
  const flags = readFlags(argv);
  if (flags === 'help') return { kind: 'help' };
  const has = (f: Flag) => flags.has(f);
  const clash = (flag: Flag, reason: string): never => {
    throw new ParameterError(`--${flag}`, `--${flag}: not allowed ${reason}`);
  };
  const gamut = oneOf('--gamut', flags.get('gamut') ?? 'clip', GAMUT_MAPPINGS);
  const format = oneOf('--format', flags.get('format') ?? 'json', OUTPUT_FORMATS);
  const thicknessTable = (['from', 'to', 'step'] as const).filter(has);
  const isTable = thicknessTable.length > 0 || has('angles');
  if (format === 'csv' && !isTable) clash('format', 'as csv without a table (--from/--to/--step or --angles)');

  if (has('cases')) {
    const other = VALUE_FLAGS.find((f) => has(f) && !['cases', 'gamut', 'format'].includes(f));
    if (other) clash(other, 'with --cases (a cases file gives every field of its cases)');
    const path = flags.get('cases') ?? '';
    return path === '' ? rejectValue('--cases', path, 'the path of a JSON file') : { kind: 'casesFile', path, gamut };
  }
  if (!isTable) return { kind: 'cases', cases: [caseFromFlags(flags)], gamut };

  if (has('angles')) {
    if (thicknessTable[0]) clash(thicknessTable[0], 'with --angles (a table varies one parameter)');
    if (has('angle')) clash('angle', 'with --angles (the table varies the angle)');
    const values = parseColonRange('--angles', flags.get('angles') ?? '', NUMBER_FIELDS.angleDeg);
    return { kind: 'table', variable: 'angleDeg', values, base: caseFromFlags(flags), gamut, format };
  }
  if (has('thickness')) clash('thickness', 'with --from/--to/--step (the table varies the thickness)');
  const missing = (['from', 'to', 'step'] as const).find((f) => !has(f));
  if (missing) {
    throw new ParameterError(`--${missing}`, `--${missing}: missing; --from, --to and --step make a thickness table together`);
  }
  const [from, to, step] = (['from', 'to', 'step'] as const).map((f) => flags.get(f) ?? '') as [string, string, string];
  const values = parseRange({ from, to, step }, NUMBER_FIELDS.thicknessNm, { from: '--from', to: '--to', step: '--step' });
  return { kind: 'table', variable: 'thicknessNm', values, base: caseFromFlags(flags), gamut, format };
}

/** Flag name → raw text, or 'help'. Rejects unknown and repeated flags and positionals. */
function readFlags(argv: readonly string[]): Map<Flag, string> | 'help' {
  const options = Object.fromEntries([...VALUE_FLAGS.map((f) => [f, { type: 'string' }]), ['help', { type: 'boolean' }]]);
  const { tokens } = parseArgs({ args: [...argv], options, strict: false, allowPositionals: true, tokens: true });
  const flags = new Map<Flag, string>();
  let help = false;
  for (const token of tokens) {
    if (token.kind !== 'option') {
      rejectValue('argument', token.kind === 'positional' ? token.value : '--', 'only flags, each --name value (see --help)');
    }
    const flag = `--${token.name}`;
    if (token.name === 'help') {
      if (token.value !== undefined) rejectValue(flag, token.value, 'no value');
      help = true;
      continue;
    }
    if (!(VALUE_FLAGS as readonly string[]).includes(token.name)) {
      throw new ParameterError(token.rawName, `${describeValue(token.rawName)}: unknown flag; expected one of ${ALL_FLAGS}`);
    }
    if (flags.has(token.name as Flag)) throw new ParameterError(flag, `${flag}: given more than once; expected it at most once`);
    // A flag with nothing after it reads as an empty value, which every check below rejects.
    // An absurdly long value is refused by the same checks (numbers are at most 32 characters),
    // so its message names the allowed range, with the value cut short.
    flags.set(token.name as Flag, token.value ?? '');
  }
  return help ? 'help' : flags;
}

/** The case the case flags describe (defaults for the rest), checked like a cases-file entry. */
function caseFromFlags(flags: Map<Flag, string>): ColorCase {
  const raw: Partial<Record<CaseField, unknown>> = {};
  const flagOf: Partial<Record<CaseField, string>> = {};
  for (const [flag, field] of Object.entries(FLAG_FIELDS) as [CaseFlag, (typeof FLAG_FIELDS)[CaseFlag]][]) {
    flagOf[field] = `--${flag}`;
    const text = flags.get(flag);
    if (text !== undefined) raw[field] = flagValue(field, `--${flag}`, text);
  }
  return validateColorCase(raw, 0, (field) => flagOf[field] ?? field);
}

/** A flag's text as the value a cases file would hold for its field. */
function flagValue(field: Exclude<CaseField, 'id'>, flag: string, text: string): unknown {
  if (field in NUMBER_FIELDS) return parseStrictNumber(flag, text, expectedNumber(NUMBER_FIELDS[field as NumberField]));
  if (field === 'wavelengthsNm') {
    const expected = `comma-separated numbers, each ${expectedNumber(WAVELENGTH_DOMAIN_NM)}`;
    return text.split(',').map((part, i) => parseStrictNumber(`${flag}[${i}]`, part, expected));
  }
  if (field === 'illuminant' && !(NAMED_ILLUMINANTS as readonly string[]).includes(text)) {
    const cct = parseStrictNumber(flag, text, ILLUMINANT_EXPECTED);
    return isInDomain(cct, DAYLIGHT_CCT_DOMAIN_K) ? { daylightCct: cct } : rejectValue(flag, text, ILLUMINANT_EXPECTED);
  }
  return text;
}

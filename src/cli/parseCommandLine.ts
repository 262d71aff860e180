import { GAMUT_MAPPINGS, type GamutMapping } from '../physics/colorConversions.ts';
import { ILLUMINANT_EXPECTED, parseIlluminant } from '../physics/illuminants.ts';
import { LIGHT_TINT_EXPECTED, parseLightTint } from '../physics/lightTint.ts';
import { mediumExpected, readMedium } from '../physics/medium.ts';
import { FIELD_THICKNESS, followsField } from '../physics/stackFilms.ts';
import { parseLayers } from '../physics/stackText.ts';
import { filmLayersOf, withOptionFilms } from '../methods/filmStacks.ts';
import { oneOf, ParameterError, rejectValue, expectedNumber } from '../input/validate.ts';
import {
  CASE_FLAGS,
  type CaseField,
  type ColorCase,
  MEDIUM_FIELDS,
  type MediumField,
  NUMBER_FIELDS,
  type NumberField,
  WAVELENGTH_DOMAIN_NM,
  validateColorCase,
} from './colorCase.ts';
import { CELL_HEIGHT_2D_PX, STRIP_HEIGHT_PX, checkChartSize } from './chartLayout.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';
import { readFlags, urlSpellings } from './readFlags.ts';
import { parseColonRange, parseRange } from './tableValues.ts';

const MODE_FLAGS = ['cases', 'from', 'to', 'step', 'angles', 'format', 'gamut', 'out', 'height'] as const;
/** A flag's name: a case flag's (from the schema) or one of MODE_FLAGS. */
type Flag = string;
const VALUE_FLAGS = [...CASE_FLAGS.map((f) => f.flag), ...MODE_FLAGS];

export const OUTPUT_FORMATS = ['json', 'csv', 'png', 'svg'] as const;
export type OutputFormat = (typeof OUTPUT_FORMATS)[number];
/** The formats that draw a chart into the file --out names, instead of printing a table. */
export const CHART_FORMATS = ['png', 'svg'] as const satisfies readonly OutputFormat[];
export type ChartFormat = (typeof CHART_FORMATS)[number];
const isChartFormat = (f: OutputFormat): f is ChartFormat => (CHART_FORMATS as readonly string[]).includes(f);

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
      readonly format: Exclude<OutputFormat, ChartFormat>;
    }
  | {
      readonly kind: 'chart';
      readonly thicknessNm: readonly number[];
      /** null: a 1-D strip at the base case's angle. */
      readonly anglesDeg: readonly number[] | null;
      readonly base: ColorCase;
      readonly gamut: GamutMapping;
      readonly format: ChartFormat;
      readonly out: string;
      readonly stripHeightPx: number;
    };

/**
 * What the command line asks for, every value checked; a ParameterError for the first bad one.
 * Pure: the cases file is named here and read by the caller.
 */
export function parseCommandLine(argv: readonly string[]): Command {
  const flags = readColorFlags(argv);
  if (flags === 'help') return { kind: 'help' };
  const has = (f: Flag) => flags.has(f);
  const clash = (flag: Flag, reason: string): never => {
    throw new ParameterError(`--${flag}`, `--${flag}: not allowed ${reason}`);
  };
  const gamut = oneOf('--gamut', flags.get('gamut') ?? 'clip', GAMUT_MAPPINGS);
  const format = oneOf('--format', flags.get('format') ?? 'json', OUTPUT_FORMATS);
  const thicknessTable = (['from', 'to', 'step'] as const).filter(has);
  const isTable = thicknessTable.length > 0 || has('angles');
  if (format !== 'json' && !isTable) clash('format', `as ${format} without a table (--from/--to/--step or --angles)`);
  if (isChartFormat(format)) return chartCommand(flags, format, gamut);
  if (has('out')) clash('out', `with --format ${format} (it prints to stdout; --out is for png and svg)`);
  if (has('height')) clash('height', `with --format ${format} (--height is for png and svg)`);

  if (has('cases')) {
    const other = VALUE_FLAGS.find((f) => has(f) && !['cases', 'gamut', 'format'].includes(f));
    if (other) clash(other, 'with --cases (a cases file gives every field of its cases)');
    const path = flags.get('cases') ?? '';
    return path === '' ? rejectValue('--cases', path, 'the path of a JSON file') : { kind: 'casesFile', path, gamut };
  }
  if (!isTable) return { kind: 'cases', cases: [caseFromFlags(flags)], gamut };

  if (has('angles')) {
    if (thicknessTable[0]) clash(thicknessTable[0], 'with --angles (a table varies one parameter; a png or svg chart may vary both)');
    if (has('angle')) clash('angle', 'with --angles (the table varies the angle)');
    const values = parseColonRange('--angles', flags.get('angles') ?? '', NUMBER_FIELDS.angleDeg);
    return { kind: 'table', variable: 'angleDeg', values, base: caseFromFlags(flags), gamut, format };
  }
  const base = caseFromFlags(flags);
  return { kind: 'table', variable: 'thicknessNm', values: thicknessRange(flags, base), base, gamut, format };
}

/** The values of --from/--to/--step; refuses --thickness, which they replace, and --layers with no layer they set. */
function thicknessRange(flags: Map<Flag, string>, base: ColorCase): number[] {
  if (flags.has('thickness')) {
    throw new ParameterError('--thickness', '--thickness: not allowed with --from/--to/--step (the table varies the thickness)');
  }
  if (!followsField(filmLayersOf(withOptionFilms(base.stack, base.films)))) {
    const message = `--layers: not allowed with --from/--to/--step without a ${FIELD_THICKNESS} layer (the table varies the thickness ${FIELD_THICKNESS})`;
    throw new ParameterError('--layers', message);
  }
  const missing = (['from', 'to', 'step'] as const).find((f) => !flags.has(f));
  if (missing) {
    throw new ParameterError(`--${missing}`, `--${missing}: missing; --from, --to and --step make a thickness table together`);
  }
  const [from, to, step] = (['from', 'to', 'step'] as const).map((f) => flags.get(f) ?? '') as [string, string, string];
  return parseRange({ from, to, step }, NUMBER_FIELDS.thicknessNm, { from: '--from', to: '--to', step: '--step' });
}

/** A chart: thickness along x (--from/--to/--step), and with --angles, angle down y. */
function chartCommand(flags: Map<Flag, string>, format: ChartFormat, gamut: GamutMapping): Command {
  const out = flags.get('out');
  if (out === undefined || out === '') return rejectValue('--out', out, `the path of the ${format} file to write`);
  const base = caseFromFlags(flags);
  const thicknessNm = thicknessRange(flags, base);
  let anglesDeg: number[] | null = null;
  if (flags.has('angles')) {
    if (flags.has('angle')) throw new ParameterError('--angle', '--angle: not allowed with --angles (the chart varies the angle)');
    if (flags.has('height')) {
      const message = `--height: not allowed with --angles (each cell of a 2-D chart is 1 × ${CELL_HEIGHT_2D_PX} px)`;
      throw new ParameterError('--height', message);
    }
    anglesDeg = parseColonRange('--angles', flags.get('angles') ?? '', NUMBER_FIELDS.angleDeg);
  }
  const heightText = flags.get('height');
  const expected = `a whole number of pixels in [${STRIP_HEIGHT_PX.min}, ${STRIP_HEIGHT_PX.max}]`;
  const stripHeightPx = heightText === undefined ? STRIP_HEIGHT_PX.fallback : parseStrictNumber('--height', heightText, expected);
  if (!Number.isInteger(stripHeightPx) || stripHeightPx < STRIP_HEIGHT_PX.min || stripHeightPx > STRIP_HEIGHT_PX.max) {
    rejectValue('--height', stripHeightPx, expected);
  }
  checkChartSize(thicknessNm.length, anglesDeg?.length ?? null, stripHeightPx);
  return { kind: 'chart', thicknessNm, anglesDeg, base, gamut, format, out, stripHeightPx };
}

/** Flag name → raw text, or 'help'. Rejects unknown and repeated flags and positionals. */
function readColorFlags(argv: readonly string[]): Map<Flag, string> | 'help' {
  const { values, switches } = readFlags(argv, { values: VALUE_FLAGS, switches: ['help'], spellings: urlSpellings(VALUE_FLAGS) });
  return switches.has('help') ? 'help' : values;
}

/** The case the case flags describe (defaults for the rest), checked like a cases-file entry. */
function caseFromFlags(flags: Map<Flag, string>): ColorCase {
  const raw: Partial<Record<CaseField, unknown>> = {};
  const flagOf: Partial<Record<CaseField, string>> = {};
  for (const { flag, field } of CASE_FLAGS) {
    flagOf[field] = `--${flag}`;
    const text = flags.get(flag);
    if (text !== undefined) raw[field] = flagValue(field, `--${flag}`, text);
  }
  return validateColorCase(raw, 0, (field) => flagOf[field] ?? field, 'orField');
}

/** A flag's text as the value a cases file would hold for its field. */
function flagValue(field: Exclude<CaseField, 'id'>, flag: string, text: string): unknown {
  if (field in NUMBER_FIELDS) return parseStrictNumber(flag, text, expectedNumber(NUMBER_FIELDS[field as NumberField]));
  if (field === 'wavelengthsNm') {
    const expected = `comma-separated numbers, each ${expectedNumber(WAVELENGTH_DOMAIN_NM)}`;
    return text.split(',').map((part, i) => parseStrictNumber(`${flag}[${i}]`, part, expected));
  }
  if (field === 'illuminant') return parseIlluminant(text) ?? rejectValue(flag, text, ILLUMINANT_EXPECTED);
  if (field === 'lightTint') return parseLightTint(text) ?? rejectValue(flag, text, LIGHT_TINT_EXPECTED);
  if (field === 'layers') return parseLayers(flag, text);
  if (field in MEDIUM_FIELDS) {
    const { role } = MEDIUM_FIELDS[field as MediumField];
    const reading = readMedium(text, role);
    if ('medium' in reading) return reading.medium;
    return rejectValue(flag, text, `${mediumExpected(role)}${reading.problem === null ? '' : ` (here ${reading.problem})`}`);
  }
  return text;
}
